#include <string>

#include "g2d/value.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::lower {

namespace {

std::string at(const Span& s) { return std::to_string(s.line) + ":" + std::to_string(s.col); }

std::string literal(const ir::Value& v) {
    return std::visit(
        [](const auto& x) -> std::string {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, long long>) return std::to_string(x);
            else if constexpr (std::is_same_v<T, double>) return rt::formatNumber(x);
            else if constexpr (std::is_same_v<T, bool>) return x ? "true" : "false";
            else if constexpr (std::is_same_v<T, std::string>) return "\"" + x + "\"";
            else if constexpr (std::is_same_v<T, ir::Vec2>) return "(" + rt::formatNumber(x.x) + ", " + rt::formatNumber(x.y) + ")";
            else if constexpr (std::is_same_v<T, ir::Vec3>)
                return "(" + rt::formatNumber(x.x) + ", " + rt::formatNumber(x.y) + ", " + rt::formatNumber(x.z) + ")";
            else return "enum " + std::to_string(x.enumId) + "." + std::to_string(x.index);
        },
        v);
}

std::string operand(const Operand& o) { return o.reg >= 0 ? "r" + std::to_string(o.reg) : literal(o.literal->value); }
std::string vec(const ir::Vec2& v) { return "(" + rt::formatNumber(v.x) + ", " + rt::formatNumber(v.y) + ")"; }
std::string h(int handle) { return "h" + std::to_string(handle); }
std::string k(int handle) { return "k" + std::to_string(handle); }

std::string attrs(const ir::Program& prog, int kind, const std::vector<AttrWrite>& ws) {
    std::string out;
    for (const auto& w : ws) out += (out.empty() ? " {" : ", ") + prog.kinds[kind].attrs[w.attr].name + " = " + operand(w.value);
    return out.empty() ? "" : out + "}";
}

}  // namespace

std::string printRewrite(const ir::Program& prog, const ir::Rule& rule, const RewriteProgram& p) {
    std::string out = "prepare\n";
    auto prepareLine = [&](const PrepareOp& op) {
        return std::visit(
                          [&](const auto& o) -> std::string {
                              using T = std::decay_t<decltype(o)>;
                              if constexpr (std::is_same_v<T, EvalLocal>) return "let L" + std::to_string(o.slot) + " <- expr " + at(o.value->span);
                              else if constexpr (std::is_same_v<T, Place>) {
                                  std::string s = "place";
                                  for (const auto& t : o.targets) s += " " + h(t.daughterNode) + "@" + vec(t.sketch);
                                  return s;
                              } else if constexpr (std::is_same_v<T, Eval>) return "r" + std::to_string(o.reg) + " <- expr " + at(o.value->span);
                              else if constexpr (std::is_same_v<T, EvalPosition>)
                                  return "r" + std::to_string(o.reg) + " <- finite position " + at(o.value->span);
                              else if constexpr (std::is_same_v<T, TakePlaced>)
                                  return "r" + std::to_string(o.reg) + " <- placed " + h(o.daughterNode);
                              else {
                                  static_assert(std::is_same_v<T, PrepareLoop>, "an operation the printer does not know");
                                  return "loop " + std::to_string(o.loop) + ": corners of " + rule.faces[p.loops[o.loop].matchFace].name;
                              }
                          },
                          op);
    };
    auto commitLine = [&](const CommitOp& op) {
        return std::visit(
                          [&](const auto& o) -> std::string {
                              using T = std::decay_t<decltype(o)>;
                              if constexpr (std::is_same_v<T, DeleteFace>) return "delete face " + rule.faces[o.matchFace].name;
                              else if constexpr (std::is_same_v<T, DeleteEdge>) return "delete edge " + rule.edges[o.matchEdge].name;
                              else if constexpr (std::is_same_v<T, BindNode>) return h(o.handle) + " = " + rule.nodes[o.matchNode].name;
                              else if constexpr (std::is_same_v<T, CreateNode>)
                                  return h(o.handle) + " = new " + prog.kinds[o.kind].name + " at r" + std::to_string(o.posReg) +
                                         attrs(prog, o.kind, o.attrs);
                              else if constexpr (std::is_same_v<T, Rewire>)
                                  return "rewire " + rule.edges[o.matchEdge].name + " " + h(o.src) + " -> " + h(o.dst);
                              else if constexpr (std::is_same_v<T, DeleteNode>) return "delete node " + rule.nodes[o.matchNode].name;
                              else if constexpr (std::is_same_v<T, SetPos>) return h(o.handle) + ".pos = r" + std::to_string(o.reg);
                              else if constexpr (std::is_same_v<T, SetRadius>) return h(o.handle) + ".radius = " + operand(o.value);
                              else if constexpr (std::is_same_v<T, InsertBetween>)
                                  return "insert " + h(o.node) + " between " + h(o.first) + " and " + h(o.second);
                              else if constexpr (std::is_same_v<T, SetNodeAttr>)
                                  return h(o.handle) + "." + prog.kinds[o.kind].attrs[o.write.attr].name + " = " + operand(o.write.value);
                              else if constexpr (std::is_same_v<T, TouchNodeValues>) return "touch values " + h(o.handle);
                              else if constexpr (std::is_same_v<T, SetNodeStyle>)
                                  return h(o.handle) + ".style." + o.style->prop + " = " + operand(o.value);
                              else if constexpr (std::is_same_v<T, BindEdge>) return k(o.handle) + " = " + rule.edges[o.matchEdge].name;
                              else if constexpr (std::is_same_v<T, SetEdgeAttr>)
                                  return k(o.handle) + "." + prog.kinds[o.kind].attrs[o.write.attr].name + " = " + operand(o.write.value);
                              else if constexpr (std::is_same_v<T, TouchEdge>) return "touch edge " + k(o.handle);
                              else if constexpr (std::is_same_v<T, CreateEdge>)
                                  return k(o.handle) + " = new " + prog.kinds[o.kind].name + " " + h(o.src) + " -> " + h(o.dst) +
                                         attrs(prog, o.kind, o.attrs);
                              else if constexpr (std::is_same_v<T, SetEdgeStyle>)
                                  return k(o.handle) + ".style." + o.style->prop + " = " + operand(o.value);
                              else if constexpr (std::is_same_v<T, BindFace>)
                                  return "f" + std::to_string(o.handle) + " = " + rule.faces[o.matchFace].name;
                              else if constexpr (std::is_same_v<T, SetFaceAttr>)
                                  return "f" + std::to_string(o.handle) + "." + prog.kinds[o.kind].attrs[o.write.attr].name + " = " +
                                         operand(o.write.value);
                              else if constexpr (std::is_same_v<T, TouchFace>) return "touch face f" + std::to_string(o.handle);
                              else if constexpr (std::is_same_v<T, CreateFace>) {
                                  std::string corners;
                                  for (int c : o.corners) corners += (corners.empty() ? "" : ", ") + h(c);
                                  return "f" + std::to_string(o.handle) + " = new " + prog.kinds[o.kind].name + "(" + corners + ")" +
                                         attrs(prog, o.kind, o.attrs);
                              } else if constexpr (std::is_same_v<T, SetFaceStyle>)
                                  return "f" + std::to_string(o.handle) + ".style." + o.style->prop + " = " + operand(o.value);
                              else if constexpr (std::is_same_v<T, CreateRingFace>)
                                  return "f" + std::to_string(o.handle) + " = new " + prog.kinds[o.kind].name + "(all turns' h" +
                                         std::to_string(p.loops[static_cast<std::size_t>(o.loop)].outerNodes + o.turnNode) + " of loop " +
                                         std::to_string(o.loop) + (o.reversed ? ", reversed" : "") + ")" + attrs(prog, o.kind, o.attrs);
                              else if constexpr (std::is_same_v<T, SplitFace>)
                                  return "split f" + std::to_string(o.face) + " by split " + std::to_string(o.split);
                              else {
                                  static_assert(std::is_same_v<T, CommitLoop>, "an operation the printer does not know");
                                  return "loop " + std::to_string(o.loop);
                              }
                          },
                          op);
    };
    for (const auto& op : p.prepare) out += "  " + prepareLine(op) + "\n";
    for (std::size_t i = 0; i < p.loops.size(); ++i) {
        const LoopProgram& l = p.loops[i];
        out += "loop " + std::to_string(i) + " over " + (l.sides ? "sides" : "corners") + " of " + rule.faces[l.matchFace].name +
               ": u = h" + std::to_string(l.outerNodes) + ", v = h" + std::to_string(l.outerNodes + 1) + ", new h" +
               std::to_string(l.outerNodes + 2) + ".., prev h" + std::to_string(l.outerNodes + 2 + l.localNodes) + ".., next h" +
               std::to_string(l.outerNodes + 2 + 2 * l.localNodes) + "..\n  per turn\n";
        for (const auto& op : l.prepare) out += "    " + prepareLine(op) + "\n";
        out += "  create\n";
        for (const auto& op : l.create) out += "    " + commitLine(op) + "\n";
        out += "  link\n";
        for (const auto& op : l.link) out += "    " + commitLine(op) + "\n";
    }
    for (std::size_t i = 0; i < p.splits.size(); ++i) {
        const SplitProgram& sp = p.splits[i];
        out += "split " + std::to_string(i) + ": corners of loop " + std::to_string(sp.loop) + ", chosen " +
               (sp.chosenReg >= 0 ? "by r" + std::to_string(sp.chosenReg) : std::string("all")) + "\n  centre\n";
        for (const auto& op : sp.makeCentre) out += "    " + commitLine(op) + "\n";
        out += "  edge\n";
        for (const auto& op : sp.makeEdge) out += "    " + commitLine(op) + "\n";
    }
    out += "commit\n";
    for (const auto& op : p.commit) out += "  " + commitLine(op) + "\n";
    std::string w;
    for (int n : p.effects.writtenNodes) w += " " + rule.nodes[n].name;
    for (int e : p.effects.writtenEdges) w += " " + rule.edges[e].name;
    for (int f : p.effects.writtenFaces) w += " " + rule.faces[f].name;
    return out + "writes" + w + "\n";
}

}  // namespace g2d::lower
