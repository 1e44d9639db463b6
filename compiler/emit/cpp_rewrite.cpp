#include "emit/cpp_rewrite.hpp"

namespace g2d::emit {

namespace {

std::string str(int i) { return std::to_string(i); }
std::string node(int h) { return "h" + str(h); }
std::string edge(int h) { return "k" + str(h); }
std::string face(int h) { return "q" + str(h); }
// The guard of a write the operation skips when the face is gone.
std::string ifAlive(bool guarded, int h) { return guarded ? "if (G.faceAlive(" + face(h) + ")) " : ""; }

}  // namespace

// An attribute's value at commit time: a literal as it is, a register as prepare kept it.
std::string RewritePrinter::attrValue(const lower::Operand& v) const {
    return v.reg >= 0 ? regName(v.reg) : cppLiteral(v.literal->value, v.literal->type);
}
// A new node's position: its register, or the origin (an axiom node without `at`).
std::string RewritePrinter::position(int posReg) const { return posReg >= 0 ? regName(posReg) : "vec2(0.0, 0.0)"; }

std::string RewritePrinter::prepare(const lower::RewriteProgram& p, const ExprContext& ctx, const std::string& in) {
    std::string out;
    if (p.placement) out += in + "std::optional<" + cppType(ir::positionType(prog_)) + "> placed[" + str(p.nodeHandles) + "];\n";
    return out + prepareOps(p.prepare, p, ctx, in);
}

// Each turn evaluates into its own registers, kept in a turn record with its corners.
std::string RewritePrinter::prepareLoop(int loop, const lower::RewriteProgram& p, const ExprContext& ctx, const std::string& in) {
    const lower::LoopProgram& l = p.loops[static_cast<std::size_t>(loop)];
    const std::string L = str(loop), turns = "turns_" + loopNames_ + "_" + L + "_", b = in + "    ", t = b + "    ";
    std::string out = in + "const std::uint32_t loopFirst" + L + " = static_cast<std::uint32_t>(" + turns + ".size());\n";
    out += in + "{\n" + b + "const FaceId lf = m.faces[" + str(l.matchFace) + "];\n";
    out += b + "const int lk = g.cornerCount(lf);\n" + b + "CornerId lc = g.firstCorner(lf);\n";
    out += b + "const NodeId l0 = g.cornerNode(lc);\n";
    out += b + "for (int lt = 0; lt < lk; ++lt, lc = g.nextCorner(lc)) {\n";
    out += t + "const NodeId lu = g.cornerNode(lc);\n" + t + "const NodeId lv = lt + 1 < lk ? g.cornerNode(g.nextCorner(lc)) : l0;\n";
    out += t + "(void)lu;\n" + t + "(void)lv;\n";
    ExprContext turn = ctx;
    const auto outer = ctx.node;
    turn.node = [outer, first = l.firstVar](int i) { return i == first ? std::string("lu") : i == first + 1 ? std::string("lv") : outer(i); };
    turn.nodeKind = [k = ctx.nodeKind, first = l.firstVar](int i) { return i >= first ? -1 : k(i); };
    const std::string saved = regPrefix_;
    regPrefix_ = "l" + L + "r";
    out += prepareOps(l.prepare, p, turn, t);
    out += t + "Turn_" + loopNames_ + "_" + L + "& T = " + turns + ".emplace_back();\n" + t + "T.u = lu;\n" + t + "T.v = lv;\n";
    for (std::size_t r = 0; r < l.registers.size(); ++r) out += t + "T." + regName(static_cast<int>(r)) + " = " + regName(static_cast<int>(r)) + ";\n";
    regPrefix_ = saved;
    out += b + "}\n" + in + "}\n";
    out += in + "const std::uint32_t loopCount" + L + " = static_cast<std::uint32_t>(" + turns + ".size()) - loopFirst" + L + ";\n";
    return out;
}

// Every turn's new nodes first (kept in loopNodes_), then every turn's
// edges and faces, which may join the neighbouring turns' nodes.
std::string RewritePrinter::commitLoop(int loop, const lower::RewriteProgram& p, const std::string& c) {
    const lower::LoopProgram& l = p.loops[static_cast<std::size_t>(loop)];
    const std::string L = str(loop), turns = "turns_" + loopNames_ + "_" + L + "_", b = c + "    ", t = b + "    ";
    const int H = l.outerNodes, n = l.localNodes;
    const std::string N = str(n);
    std::string out = c + "{\n" + b + "const std::uint32_t lfirst = p.loopFirst" + L + ", lcount = p.loopCount" + L + ";\n";
    out += b + "loopNodes_.assign(std::size_t{lcount} * " + N + ", kNoId);\n";
    const std::string saved = regPrefix_;
    regPrefix_ = "l" + L + "r";
    auto turnHead = [&]() {
        std::string h = t + "const Turn_" + loopNames_ + "_" + L + "& T = " + turns + "[lfirst + lt];\n";
        h += t + "const NodeId h" + str(H) + " = T.u;\n" + t + "const NodeId h" + str(H + 1) + " = T.v;\n";
        h += t + "(void)h" + str(H) + ";\n" + t + "(void)h" + str(H + 1) + ";\n";
        for (std::size_t r = 0; r < l.registers.size(); ++r)
            h += t + "const auto& " + regName(static_cast<int>(r)) + " = T." + regName(static_cast<int>(r)) + ";\n" + t + "(void)" +
                 regName(static_cast<int>(r)) + ";\n";
        return h;
    };
    out += b + "for (std::uint32_t lt = 0; lt < lcount; ++lt) {\n" + turnHead();
    out += commitOps(l.create, p, t);
    for (int i = 0; i < n; ++i) out += t + "loopNodes_[std::size_t{lt} * " + N + " + " + str(i) + "] = h" + str(H + 2 + i) + ";\n";
    out += b + "}\n";
    out += b + "for (std::uint32_t lt = 0; lt < lcount; ++lt) {\n" + turnHead();
    for (int i = 0; i < n; ++i) {
        const std::string at = " * " + N + " + " + str(i) + "];\n";
        out += t + "const NodeId h" + str(H + 2 + i) + " = loopNodes_[std::size_t{lt}" + at;
        out += t + "const NodeId h" + str(H + 2 + n + i) + " = loopNodes_[std::size_t{(lt + lcount - 1) % lcount}" + at;
        out += t + "const NodeId h" + str(H + 2 + 2 * n + i) + " = loopNodes_[std::size_t{(lt + 1) % lcount}" + at;
        for (int k : {H + 2 + i, H + 2 + n + i, H + 2 + 2 * n + i}) out += t + "(void)h" + str(k) + ";\n";
    }
    out += commitOps(l.link, p, t);
    out += b + "}\n" + c + "}\n";
    regPrefix_ = saved;
    return out;
}

// A face over node turnNode of every turn of a loop, right after its commit
// (loopNodes_ still holds the loop's new nodes).
std::string RewritePrinter::ringFace(const lower::CreateRingFace& o, const lower::RewriteProgram& p, const std::string& c) {
    const lower::LoopProgram& l = p.loops[static_cast<std::size_t>(o.loop)];
    const std::string L = str(o.loop), b = c + "    ", n = "p.loopCount" + L;
    std::string out = c + "ringCorners_.clear();\n" + c + "for (std::uint32_t lk = 0; lk < " + n + "; ++lk) {\n";
    out += b + "const std::uint32_t lt = " + (o.reversed ? n + " - 1 - lk" : std::string("lk")) + ";\n";
    out += b + "const Turn_" + loopNames_ + "_" + L + "& T = turns_" + loopNames_ + "_" + L + "_[p.loopFirst" + L + " + lt];\n";
    out += b + "(void)T;\n";
    const std::string corner = o.turnNode == 0   ? "T.u"
                               : o.turnNode == 1 ? "T.v"
                                                 : "loopNodes_[std::size_t{lt} * " + str(l.localNodes) + " + " + str(o.turnNode - 2) + "]";
    out += b + "ringCorners_.push_back(" + corner + ");\n" + c + "}\n";
    out += c + "const FaceId " + face(o.handle) + " = addDaughterFace(G, " + str(o.kind) + ", ringCorners_, step, " + (o.orient ? "true" : "false") + ");\n" + c + "(void)" + face(o.handle) + ";\n";
    return out + record(o.kind, o.attrs, face(o.handle), ir::ElemClass::Face, c);
}

// The chosen corners from the split's corner loop, then the cut
// (rt::splitFace), whose makers are the split's operations as lambdas.
std::string RewritePrinter::splitFace(const lower::SplitFace& o, const lower::RewriteProgram& p, const std::string& c) {
    const lower::SplitProgram& s = p.splits[static_cast<std::size_t>(o.split)];
    const std::string L = str(s.loop), b = c + "    ", t = b + "    ";
    std::string out = c + "{\n" + b + "splitChosen_.clear();\n";
    out += b + "for (std::uint32_t lt = 0; lt < p.loopCount" + L + "; ++lt) {\n";
    out += t + "const Turn_" + loopNames_ + "_" + L + "& T = turns_" + loopNames_ + "_" + L + "_[p.loopFirst" + L + " + lt];\n";
    out += t + (s.chosenReg >= 0 ? "if (T." + loopReg(s.loop, s.chosenReg) + ") " : std::string()) + "splitChosen_.push_back(T.u);\n";
    out += b + "}\n" + b + "SplitMakers make;\n";
    if (!s.makeCentre.empty())
        out += b + "make.centre = [&]() -> NodeId {\n" + commitOps(s.makeCentre, p, t) + t + "return " + node(s.to) + ";\n" + b + "};\n";
    out += b + "make.edge = [&](NodeId " + node(s.from) + ", NodeId " + node(s.to) + ") -> EdgeId {\n" + commitOps(s.makeEdge, p, t) + t +
           "return " + edge(s.edgeHandle) + ";\n" + b + "};\n";
    out += b + "make.copyFace = [&](FaceId from, FaceId to) { copyFaceAttributes(G, from, to); };\n";
    return out + b + "splitFace(G, " + face(o.face) + ", splitChosen_, make, step);\n" + c + "}\n";
}

std::string RewritePrinter::prepareOps(const std::vector<lower::PrepareOp>& ops, const lower::RewriteProgram& p, const ExprContext& ctx,
                                       const std::string& in) {
    std::string out;
    for (const auto& op : ops) {
        std::visit(lower::Overloaded{
                       [&](const lower::EvalLocal& o) {
                           const std::string v = gen_.gen(*o.value, ctx, out, in);
                           const std::string l = "L" + str(o.slot);
                           out += in + "const " + cppType(o.value->type) + " " + l + " = " + v + ";\n" + in + "(void)" + l + ";\n";
                       },
                       [&](const lower::Place& o) { out += placement(o, in); },
                       [&](const lower::Eval& o) {
                           const std::string v = gen_.gen(*o.value, ctx, out, in);
                           out += in + "const auto " + regName(o.reg) + " = " + v + ";\n";
                       },
                       [&](const lower::EvalPosition& o) {
                           const std::string v = gen_.gen(*o.value, ctx, out, in);
                           out += in + "const " + cppType(ir::positionType(prog_)) + " " + regName(o.reg) + " = " + v + ";\n";
                           out += in + "if (!isFinitePosition(" + regName(o.reg) + ")) throw PlacedError(" +
                                  str(places_.add(o.value->span)) + ", " + cppString(o.message) + ");\n";
                       },
                       [&](const lower::TakePlaced& o) {
                           out += in + "const " + cppType(ir::positionType(prog_)) + " " + regName(o.reg) + " = *placed[" + str(o.daughterNode) + "];\n";
                       },
                       [&](const lower::PrepareLoop& o) { out += prepareLoop(o.loop, p, ctx, in); },
                   },
                   op);
    }
    return out;
}

std::string RewritePrinter::commit(const lower::RewriteProgram& p, const std::string& c) {
    return c + "(void)step;\n" + c + "(void)G;\n" + commitOps(p.commit, p, c);
}

std::string RewritePrinter::commitOps(const std::vector<lower::CommitOp>& ops, const lower::RewriteProgram& p, const std::string& c) {
    std::string commit;
    for (const auto& op : ops) {
        std::visit(lower::Overloaded{
                       [&](const lower::DeleteFace& o) { commit += c + "G.removeFace(m.faces[" + str(o.matchFace) + "]);\n"; },
                       [&](const lower::DeleteEdge& o) { commit += c + "G.removeEdge(m.edges[" + str(o.matchEdge) + "]);\n"; },
                       [&](const lower::BindNode& o) {
                           commit += c + "const NodeId " + node(o.handle) + " = m.nodes[" + str(o.matchNode) + "];\n" + c + "(void)" + node(o.handle) + ";\n";
                       },
                       [&](const lower::CreateNode& o) {
                           commit += c + "const NodeId " + node(o.handle) + " = G.addNode(" + str(o.kind) + ", " + position(o.posReg) + ", step);\n" + c +
                                     "(void)" + node(o.handle) + ";\n" + record(o.kind, o.attrs, node(o.handle), ir::ElemClass::Node, c);
                       },
                       [&](const lower::Rewire& o) {
                           commit += c + "G.reconnectEdge(m.edges[" + str(o.matchEdge) + "], " + node(o.src) + ", " + node(o.dst) + ");\n";
                       },
                       [&](const lower::DeleteNode& o) { commit += c + "G.removeNode(m.nodes[" + str(o.matchNode) + "]);\n"; },
                       [&](const lower::SetPos& o) { commit += c + "G.setPos(" + node(o.handle) + ", " + regName(o.reg) + ");\n"; },
                       [&](const lower::InsertBetween& o) {
                           commit += c + "insertDaughterCorner(G, " + node(o.first) + ", " + node(o.second) + ", " + node(o.node) + ");\n";
                       },
                       [&](const lower::SetRadius& o) { commit += c + "G.setRadius(" + node(o.handle) + ", " + attrValue(o.value) + ");\n"; },
                       [&](const lower::SetNodeAttr& o) {
                           commit += c + gen_.attrAccess(o.kind, node(o.handle), ir::ElemClass::Node, o.write.attr, "G") + " = " + attrValue(o.write.value) + ";\n";
                       },
                       [&](const lower::TouchNodeValues& o) { commit += c + "G.touchNodeValues(" + node(o.handle) + ");\n"; },
                       [&](const lower::SetNodeStyle& o) {
                           commit += c + "G.setNodeStyle(" + node(o.handle) + ", " + cppStyleProp(*o.style) + ", " + styleValue(o.value) + ");\n";
                       },
                       [&](const lower::BindEdge& o) {
                           commit += c + "const EdgeId " + edge(o.handle) + " = m.edges[" + str(o.matchEdge) + "];\n" + c + "(void)" + edge(o.handle) + ";\n";
                       },
                       [&](const lower::SetEdgeAttr& o) {
                           commit += c + gen_.attrAccess(o.kind, edge(o.handle), ir::ElemClass::Edge, o.write.attr, "G") + " = " + attrValue(o.write.value) + ";\n";
                       },
                       [&](const lower::TouchEdge& o) { commit += c + "G.touchEdgeItself(" + edge(o.handle) + ");\n"; },
                       [&](const lower::CreateEdge& o) {
                           commit += c + "const EdgeId " + edge(o.handle) + " = G.addEdge(" + str(o.kind) + ", " + node(o.src) + ", " + node(o.dst) +
                                     ", step);\n" + c + "(void)" + edge(o.handle) + ";\n" + record(o.kind, o.attrs, edge(o.handle), ir::ElemClass::Edge, c);
                       },
                       [&](const lower::SetEdgeStyle& o) {
                           commit += c + "G.setEdgeStyle(" + edge(o.handle) + ", " + cppStyleProp(*o.style) + ", " + styleValue(o.value) + ");\n";
                       },
                       [&](const lower::BindFace& o) {
                           commit += c + "const FaceId " + face(o.handle) + " = m.faces[" + str(o.matchFace) + "];\n" + c + "(void)" + face(o.handle) + ";\n";
                       },
                       [&](const lower::SetFaceAttr& o) {
                           commit += c + ifAlive(o.ifAlive, o.handle) +
                                     gen_.attrAccess(o.kind, face(o.handle), ir::ElemClass::Face, o.write.attr, "G") + " = " + attrValue(o.write.value) + ";\n";
                       },
                       [&](const lower::TouchFace& o) {
                           commit += c + ifAlive(o.ifAlive, o.handle) + "G.touchFaceValues(" + face(o.handle) + ");\n";
                       },
                       [&](const lower::CreateFace& o) {
                           std::string corners;
                           for (int n : o.corners) corners += (corners.empty() ? "" : ", ") + node(n);
                           commit += c + "const FaceId " + face(o.handle) + " = addDaughterFace(G, " + str(o.kind) + ", std::array<NodeId, " +
                                     str(static_cast<int>(o.corners.size())) + ">{" + corners + "}, step, " + (o.orient ? "true" : "false") + ");\n" + c + "(void)" + face(o.handle) +
                                     ";\n" + record(o.kind, o.attrs, face(o.handle), ir::ElemClass::Face, c);
                       },
                       [&](const lower::SetFaceStyle& o) {
                           commit += c + ifAlive(o.ifAlive, o.handle) + "G.setFaceStyle(" + face(o.handle) + ", " + cppStyleProp(*o.style) + ", " + styleValue(o.value) + ");\n";
                       },
                       [&](const lower::CommitLoop& o) { commit += commitLoop(o.loop, p, c); },
                       [&](const lower::CreateRingFace& o) { commit += ringFace(o, p, c); },
                       [&](const lower::SplitFace& o) { commit += splitFace(o, p, c); },
                   },
                   op);
    }
    return commit;
}

// A style's value: a literal is one shared constant of the grammar.
std::string RewritePrinter::styleValue(const lower::Operand& v) {
    if (v.reg < 0) return constants_.add(valueInit(v.type, cppLiteral(v.literal->value, v.literal->type)));
    return valueOf(v.type, regName(v.reg));
}

// A new element's attribute record: the kind's defaults, then the rewrite's values.
std::string RewritePrinter::record(int kind, const std::vector<lower::AttrWrite>& attrs, const std::string& element, ir::ElemClass cls,
                   const std::string& c) const {
    if (prog_.kinds[kind].attrs.empty()) return "";
    std::string out = c + "{\n" + c + "    Kind" + str(kind) + " rec = default_" + str(kind) + ";\n";
    for (const auto& w : attrs) out += c + "    rec.a" + str(w.attr) + " = " + attrValue(w.value) + ";\n";
    const char* setSlot = cls == ir::ElemClass::Edge ? "setEdgeSlot" : cls == ir::ElemClass::Face ? "setFaceSlot" : "setNodeSlot";
    return out + c + "    G." + setSlot + "(" + element + ", store_" + str(kind) + ".add(rec));\n" + c + "}\n";
}

std::string RewritePrinter::placement(const lower::Place& o, const std::string& in) {
    std::string out = in + "{\n";
    const std::string b = in + "    ";
    // Fixed-size arrays: placement allocates nothing per step.
    std::string mother, host, refDaughter, refHost, refZ;
    auto item = [](std::string& list, const std::string& v) { list += (list.empty() ? "" : ", ") + v; };
    auto vec = [](const ir::Vec2& v) { return cppLiteral(ir::Value{v}, ir::kVec2Type); };
    for (std::size_t i = 0; i < o.motherSketch.size(); ++i) {
        item(mother, vec(o.motherSketch[i]));
        item(host, "g.pos(m.nodes[" + str(o.members[i]) + "])");
    }
    for (const auto& [sketch, node] : o.refs) {
        item(refDaughter, vec(sketch));
        item(refHost, "g.pos(m.nodes[" + str(node) + "])");
        item(refZ, "g.z(m.nodes[" + str(node) + "])");
    }
    // std::array: a rule whose match has no placed node has none (a C array may not be empty).
    const std::string nodes = str(static_cast<int>(o.motherSketch.size()));
    out += b + "const std::array<vec2, " + nodes + "> mother{{" + mother + "}};\n";
    out += b + "const std::array<vec2, " + nodes + "> host{{" + host + "}};\n";
    const std::string n = str(static_cast<int>(o.refs.size()));
    out += b + "const std::array<vec2, " + n + "> refDaughter{{" + refDaughter + "}};\n";
    out += b + "const std::array<vec2, " + n + "> refHost{{" + refHost + "}};\n";
    const std::string directed =
        o.directed ? "std::make_pair(" + str(o.directed->first) + ", " + str(o.directed->second) + ")" : "std::nullopt";
    if (o.space3d) out += b + "const std::array<double, " + n + "> refZ{{" + refZ + "}};\n";
    out += b + "const PlacementFrame frame = placementFrame(mother, host, " + directed + ", refDaughter, refHost" +
           (o.space3d ? ", refZ" : "") + ");\n";
    for (const auto& t : o.targets) {
        const std::string si = str(t.daughterNode);
        out += b + "placed[" + si + "] = frame." + (o.space3d ? "place3(" : "place(") + vec(t.sketch) + ");\n";
        out += b + "if (!std::isfinite(placed[" + si + "]->x) || !std::isfinite(placed[" + si + "]->y)) throw PlacedError(" +
               str(places_.add(t.span)) + ", " + cppString(t.message) + ");\n";
    }
    return out + in + "}\n";
}

}  // namespace g2d::emit
