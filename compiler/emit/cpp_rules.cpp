#include "emit/cpp_rules.hpp"

#include <algorithm>

#include "emit/cpp_rewrite.hpp"

namespace g2d::emit {


namespace {

std::string str(int i) { return std::to_string(i); }

class RuleEmitter {
public:
    RuleEmitter(const ir::Program& prog, const lower::LoweredRule& lowered, int index, int firstDaughter, ExprGen& gen,
                Places& places, ConstantValues& constants)
        : prog_(prog), r_(*lowered.rule), ri_(str(index)), firstDaughter_(firstDaughter), gen_(gen),
          rewrite_(prog, gen, places, constants), match_(lowered.match), facts_(lowered.facts), daughters_(lowered.daughters) {}

    std::string emit() {
        std::string out;
        out += matcher(-1);
        for (std::size_t a = 0; a < r_.nodes.size(); ++a) out += matcher(static_cast<int>(a));
        out += repair();
        for (std::size_t k = 0; k < r_.nacs.size(); ++k) out += nac(static_cast<int>(k));
        for (std::size_t d = 0; d < r_.daughters.size(); ++d) {
            const lower::RewriteProgram& p = daughters_[d];
            out += writeSet(static_cast<int>(d), p);
            out += prepare(static_cast<int>(d), p);
        }
        return out;
    }

private:
    ExprContext matchContext(const ir::NegativeCondition* nac) const {
        ExprContext c;
        c.node = [](int i) { return "n[" + str(i) + "]"; };
        c.edge = [](int i) { return "e[" + str(i) + "]"; };
        c.nodeKind = [this, nac](int i) { return ir::slotNodeKind(r_, nac, i); };
        c.edgeKind = [this, nac](int i) { return ir::slotEdge(r_, nac, i).kind; };
        c.face = [](int i) { return "f[" + str(i) + "]"; };
        c.faceKind = [this, nac](int i) { return ir::slotFace(r_, nac, i).kind; };
        return c;
    }

    // The lowering's `ordered` comparisons for node `k`, as a C++ test ("" for none).
    static std::string orderedTest(int k, const std::vector<lower::OrderCheck>& checks) {
        std::string test;
        for (const auto& c : checks) {
            const char* axis = c.axis == 0 ? ".x" : ".y";
            const std::string hi = "g.pos(n[" + str(k) + "])" + axis, hj = "g.pos(n[" + str(c.other) + "])" + axis;
            test += (test.empty() ? "" : " && ") + std::string("!(") + hi + (c.before ? " > " : " < ") + hj + ")";
        }
        return test;
    }
    // The test that host `h` has had every edge kind of `mask` ("" for none).
    static std::string hasEdgeKinds(std::uint32_t mask, const std::string& h) {
        if (mask == 0) return "";
        const std::string need = str(static_cast<int>(mask)) + "u";
        return "(g.edgeKindsAt(" + h + ") & " + need + ") == " + need;
    }

    // Nested blocks for plan[i..]; `onComplete` is the innermost code.
    // Set while a search that keeps only matches binding a new edge is
    // generated: a test, true for a binding to drop, emitted where the last
    // of the pattern's edges is bound.
    std::string newEdgeGate_;
    // Whether the bound pattern edges include one whose id is at least `from`.
    std::string bindsNewEdge(const std::string& from) const {
        std::string t = "false";
        for (std::size_t k = 0; k < r_.edges.size(); ++k) t += " || e[" + str(static_cast<int>(k)) + "] >= " + from;
        return t;
    }

    // Nested blocks for ops[i..]; `onComplete` is the innermost code. `nac`
    // names the negative condition the list searches (for its slots' kinds
    // in expressions), null for the pattern.
    void steps(const lower::MatchList& ops, std::size_t i, const ir::NegativeCondition* nac, const std::string& onComplete,
               std::string& out, const std::string& in) {
        if (i == ops.size()) {
            out += onComplete;
            return;
        }
        const std::string next = in + "    ";
        const std::string body = next + "    ";
        auto notUsed = [](const std::string& h, const std::vector<int>& slots, const char* array) {
            std::string t;
            for (int b : slots) t += " && " + h + " != " + array + "[" + str(b) + "]";
            return t;
        };
        auto gate = [&](bool here) { return here && !newEdgeGate_.empty() ? body + "if (" + newEdgeGate_ + ") continue;\n" : std::string(); };
        std::visit(lower::Overloaded{
                       [&](const lower::Filter& o) {
                           out += in + "{\n";
                           const std::string v = gen_.gen(*o.condition, matchContext(nac), out, next);
                           out += next + "if (" + v + ") {\n";
                           steps(ops, i + 1, nac, onComplete, out, next + "    ");
                           out += next + "}\n" + in + "}\n";
                       },
                       [&](const lower::ScanNodes& o) {
                           const std::string c = "c" + str(static_cast<int>(i)), l = "l" + str(static_cast<int>(i));
                           const std::string nd = "n[" + str(o.node) + "]";
                           if (o.kind >= 0) {
                               out += in + "{\n" + next + "const auto " + l + " = g.nodesOfKind(" + str(o.kind) + ");\n";
                               out += next + "for (std::size_t " + c + " = 0; " + c + " < " + l + ".size(); ++" + c + ") {\n";
                               out += body + nd + " = " + l + "[" + c + "];\n";
                           } else {   // a wildcard: every live node, by id
                               out += in + "{\n" + next + "for (const NodeId " + c + " : g.allNodes()) {\n";
                               out += body + nd + " = " + c + ";\n";
                           }
                           std::string test = "true" + notUsed(nd, o.distinctNodes, "n");
                           if (const std::string kinds = hasEdgeKinds(o.edgeKinds, nd); !kinds.empty()) test += " && " + kinds;
                           if (const std::string ord = orderedTest(o.node, o.ordered); !ord.empty()) test += " && " + ord;
                           out += body + "if (" + test + ") {\n";
                           steps(ops, i + 1, nac, onComplete, out, body + "    ");
                           out += body + "}\n" + next + "}\n" + in + "}\n";
                       },
                       [&](const lower::ExtendEdge& o) {
                           const std::string from = "n[" + str(o.from) + "]";
                           const std::string ed = "e[" + str(o.edge) + "]", nd = "n[" + str(o.node) + "]";
                           out += in + "{\n" + edgeLoop(static_cast<int>(i), from, ed, o.directed, o.fromIsSource, next);
                           const std::string used = notUsed(ed, o.distinctEdges, "e");
                           out += body + "if (g.edgeKind(" + ed + ") != " + str(o.kind) + (used.empty() ? "" : " || !(true" + used + ")") +
                                  ") continue;\n";
                           out += gate(o.newEdgeGate);
                           if (o.directed)
                               out += body + nd + " = " + (o.fromIsSource ? "g.target(" : "g.source(") + ed + ");\n";
                           else
                               out += body + nd + " = g.source(" + ed + ") == " + from + " ? g.target(" + ed + ") : g.source(" + ed + ");\n";
                           std::string test = o.nodeKind >= 0 ? "g.nodeKind(" + nd + ") == " + str(o.nodeKind) : "true";
                           test += notUsed(nd, o.distinctNodes, "n");
                           if (const std::string ord = orderedTest(o.node, o.ordered); !ord.empty()) test += " && " + ord;
                           out += body + "if (" + test + ") {\n";
                           steps(ops, i + 1, nac, onComplete, out, body + "    ");
                           out += body + "}\n" + next + "}\n" + in + "}\n";
                       },
                       [&](const lower::ScanNear& o) {
                           const std::string c = "c" + str(static_cast<int>(i)), l = "l" + str(static_cast<int>(i));
                           const std::string nd = "n[" + str(o.node) + "]";
                           out += in + "{\n";
                           const std::string centre = gen_.gen(*o.centre, matchContext(nac), out, next);
                           const std::string radius = gen_.gen(*o.radius, matchContext(nac), out, next);
                           const std::string at = prog_.space3d ? centre : "vec3(" + centre + ", 0.0)";
                           if (o.join)   // copied: a later piece's join asks again while this one is walked
                               out += next + "const std::vector<NodeId> " + l + " = asVector(nearQueries().nodesAround(g, " + str(o.kind) + ", " + at +
                                      ", static_cast<double>(" + radius + ")));\n";
                           else
                               out += next + "const auto " + l + " = nearQueries().nodesNear(g, " + ri_ + ", " + str(o.near) + ", n[" + str(o.key) + "], " +
                                      str(o.kind) + ", " + at + ", static_cast<double>(" + radius + "));\n";
                           out += next + "for (std::size_t " + c + " = 0; " + c + " < " + l + ".size(); ++" + c + ") {\n";
                           out += body + nd + " = " + l + "[" + c + "];\n";
                           const std::string kinds = o.edgeKinds ? " && (g.edgeKindsAt(" + nd + ") & " + str(static_cast<long long>(o.edgeKinds)) + "u) == " +
                                                                       str(static_cast<long long>(o.edgeKinds)) + "u" : "";
                           out += body + "if (true" + notUsed(nd, o.distinctNodes, "n") + kinds + ") {\n";
                           steps(ops, i + 1, nac, onComplete, out, body + "    ");
                           out += body + "}\n" + next + "}\n" + in + "}\n";
                       },
                       [&](const lower::MatchFace& o) { bindFace(o, static_cast<int>(i), [&](std::string& o2, const std::string& in2) {
                                                              steps(ops, i + 1, nac, onComplete, o2, in2);
                                                          }, out, in); },
                       [&](const lower::ConnectEdge& o) {
                           const std::string hs = "n[" + str(o.from) + "]", hd = "n[" + str(o.to) + "]";
                           const std::string ed = "e[" + str(o.edge) + "]";
                           out += in + "{\n" + edgeLoop(static_cast<int>(i), hs, ed, o.directed, true, next);
                           const std::string used = notUsed(ed, o.distinctEdges, "e");
                           out += body + "if (g.edgeKind(" + ed + ") != " + str(o.kind) + (used.empty() ? "" : " || !(true" + used + ")") +
                                  ") continue;\n";
                           const std::string a = "g.source(" + ed + ")", b = "g.target(" + ed + ")";
                           const std::string fits = o.directed ? "(" + b + " == " + hd + ")"
                                                               : "((" + a + " == " + hs + " && " + b + " == " + hd + ") || (" + a +
                                                                     " == " + hd + " && " + b + " == " + hs + "))";
                           out += body + "if (!" + fits + ") continue;\n";
                           out += gate(o.newEdgeGate);
                           out += body + "{\n";
                           steps(ops, i + 1, nac, onComplete, out, body + "    ");
                           out += body + "}\n" + next + "}\n" + in + "}\n";
                       },
                   },
                   ops[i]);
    }

    // A face and its corners (lower::MatchFace): the candidate faces, then
    // per rotation the corners tested or bound in order, then `inner`.
    template <class Inner>
    void bindFace(const lower::MatchFace& o, int step, const Inner& inner, std::string& out, const std::string& in) {
        const std::string next = in + "    ", body = next + "    ";
        const std::string s = str(step), fc = "f[" + str(o.face) + "]", k = str(static_cast<int>(o.corners.size()));
        std::string faceTest = "g.faceKind(" + fc + ") == " + str(o.kind);
        if (!o.anyCount) faceTest += " && g.cornerCount(" + fc + ") == " + k;
        for (int d : o.distinctFaces) faceTest += " && " + fc + " != f[" + str(d) + "]";
        out += in + "{\n";
        std::string rotations;   // the loop over the rotations to try, opened at `body`
        if (o.from < 0) {
            out += next + "const auto fl" + s + " = g.facesOfKind(" + str(o.kind) + ");\n";
            out += next + "for (std::size_t fi" + s + " = 0; fi" + s + " < fl" + s + ".size(); ++fi" + s + ") {\n";
            out += body + fc + " = fl" + s + "[fi" + s + "];\n";
            out += body + "if (!(" + faceTest + ")) continue;\n";
            out += body + "CornerId st" + s + " = g.firstCorner(" + fc + ");\n";
            out += body + "for (int r" + s + " = 0; r" + s + " < " + (o.anyCount ? "1" : k) + "; ++r" + s + ", st" + s + " = g.nextCorner(st" + s + ")) {\n";
        } else {
            out += next + "for (CornerId at" + s + " = g.firstCornerAt(n[" + str(o.from) + "]); at" + s + " != kNoId; at" + s +
                   " = g.nextCornerAt(at" + s + ")) {\n";
            out += body + fc + " = g.cornerFace(at" + s + ");\n";
            if (o.anyCount) faceTest += " && at" + s + " == g.firstCorner(" + fc + ")";
            out += body + "if (!(" + faceTest + ")) continue;\n";
            out += body + "CornerId st" + s + " = at" + s + ";\n";
            for (int j = 0; j < o.fromCorner; ++j) out += body + "st" + s + " = g.prevCorner(st" + s + ");\n";
            out += body + "{\n";
        }
        const std::string inner1 = body + "    ";
        out += inner1 + "CornerId cc" + s + " = st" + s + ";\n";
        std::string test = "true";
        for (std::size_t j = 0; j < o.corners.size(); ++j) {
            const std::string nd = "n[" + str(o.corners[j]) + "]", h = "g.cornerNode(cc" + s + ")";
            if (j > 0) out += inner1 + "cc" + s + " = g.nextCorner(cc" + s + ");\n";
            if (o.cornerBound[j]) {
                out += inner1 + "if (" + h + " != " + nd + ") continue;\n";
                continue;
            }
            out += inner1 + nd + " = " + h + ";\n";
            std::string t = o.cornerKinds[j] >= 0 ? "g.nodeKind(" + nd + ") != " + str(o.cornerKinds[j]) : "";
            for (int d : o.distinctNodes) t += (t.empty() ? "" : " || ") + nd + " == n[" + str(d) + "]";
            if (!t.empty()) out += inner1 + "if (" + t + ") continue;\n";
        }
        (void)test;
        out += inner1 + "{\n";
        inner(out, inner1 + "    ");
        out += inner1 + "}\n" + body + "}\n" + next + "}\n" + in + "}\n";
    }

    // The loop header over the edges at `from` that may bind `ed`: a directed
    // edge among `from`'s outgoing (or incoming) edges only, an undirected one
    // among both (outgoing first, self-loops once), as the interpreter.
    static std::string edgeLoop(int step, const std::string& from, const std::string& ed, bool directed, bool outgoing,
                                const std::string& in) {
        const std::string x = "x" + str(step);
        if (directed) {
            const std::string first = outgoing ? "g.firstOut(" : "g.firstIn(", next = outgoing ? "g.nextOut(" : "g.nextIn(";
            return in + "for (EdgeId " + x + " = " + first + from + "); " + x + " != kNoId; " + x + " = " + next + x + ")) {\n" +
                   in + "    " + ed + " = " + x + ";\n";
        }
        const std::string ph = "ph" + str(step);
        return in + "for (int " + ph + " = 0; " + ph + " < 2; ++" + ph + ")\n" + in + "for (EdgeId " + x + " = " + ph +
               " == 0 ? g.firstOut(" + from + ") : g.firstIn(" + from + "); " + x + " != kNoId; " + x + " = " + ph +
               " == 0 ? g.nextOut(" + x + ") : g.nextIn(" + x + ")) {\n" + in + "    if (" + ph + " == 1 && g.source(" + x +
               ") == g.target(" + x + ")) continue;\n" + in + "    " + ed + " = " + x + ";\n";
    }

    std::string arrays() const { return str(match_.nodeSlots) + "], e[" + str(match_.edgeSlots) + "], f[" + str(match_.faceSlots); }

    // The full matcher (anchor -1), or the one with pattern node `anchor` bound to `host`.
    std::string matcher(int anchor) {
        std::string out = anchor < 0 ? "    void match_" + ri_ + "(const Graph& g, MatchBuffer& out) {\n"
                                     : "    void match_" + ri_ + "_a" + str(anchor) +
                                           "(const Graph& g, NodeId host, MatchBuffer& out, EdgeId newFrom) {\n";
        out += "        NodeId n[" + arrays() + "];\n";
        out += "        std::fill(std::begin(n), std::end(n), kNoId);\n        std::fill(std::begin(e), std::end(e), kNoId);\n"
               "        std::fill(std::begin(f), std::end(f), kNoId);\n";
        if (anchor >= 0) out += "        n[" + str(anchor) + "] = host;\n";
        out += "        (void)g;\n";   // an empty pattern reads nothing
        if (anchor >= 0)
            if (const std::string kinds = hasEdgeKinds(match_.anchorEdgeKinds[static_cast<std::size_t>(anchor)], "host"); !kinds.empty())
                out += "        if (!(" + kinds + ")) return;\n";
        std::string complete = "";
        std::string nacTest = "true";
        for (std::size_t k = 0; k < r_.nacs.size(); ++k) nacTest += " && !nac_" + ri_ + "_" + str(static_cast<int>(k)) + "(g, n, e, f)";
        const std::string push = "out.add(n, e, f);";
        std::string body;
        if (anchor < 0) {
            steps(match_.full, 0, nullptr, "@@COMPLETE@@", body, "        ");
        } else {
            out += "        (void)newFrom;\n";
            newEdgeGate_ = "newFrom != kNoId && !(" + bindsNewEdge("newFrom") + ")";
            steps(match_.anchored[static_cast<std::size_t>(anchor)], 0, nullptr, "@@COMPLETE@@", body, "        ");
            newEdgeGate_.clear();
        }
        // The innermost code, indented where it lands.
        const auto at = body.find("@@COMPLETE@@");
        const auto lineStart = body.rfind('\n', at) + 1;
        const std::string indent = body.substr(lineStart, at - lineStart);
        (void)indent;
        body.replace(at, 12, "if (" + nacTest + ") " + push + "\n");
        return out + body + "    }\n\n";
    }

    // RuleSet::repair for this rule: the anchored searches inlined, in the
    // generic loop's order (area nodes, then pattern nodes), adding straight
    // into the match set; its decisions are RepairArea's, on the anchors
    // both back ends take from rt::repairAnchors.
    std::string repair() {
        const std::vector<rt::RepairAnchor> anchors = rt::repairAnchors(facts_.info);
        const std::string table = "kAnchors_" + ri_;
        std::string out = "    static constexpr RepairAnchor " + table + "[] = {";
        for (std::size_t p = 0; p < anchors.size(); ++p) {
            const auto& a = anchors[p];
            out += std::string(p ? ", " : "") + "{" + str(a.kind) + ", " + str(a.directions) + ", " + (a.readsAllEdges ? "true" : "false") +
                   ", " + (a.newHostAddsNothing ? "true" : "false") + "}";
        }
        if (anchors.empty()) out += "{}";
        out += "};\n";
        out += "    void repair_" + ri_ + "(const Graph& g, const RepairArea& area, MatchSet& set) {\n";
        out += "        NodeId n[" + arrays() + "];\n";
        if (r_.nodes.empty()) out += "        (void)n;\n        (void)e;\n        (void)f;\n        (void)set;\n";   // an empty pattern
        std::string nacTest = "true";
        for (std::size_t k = 0; k < r_.nacs.size(); ++k) nacTest += " && !nac_" + ri_ + "_" + str(static_cast<int>(k)) + "(g, n, e, f)";
        out += "        for (const NodeId h : area.nodes) {\n            if (!g.nodeAlive(h)) continue;\n";
        out += "            const bool full = area.full(h);\n            const int hk = g.nodeKind(h);\n            (void)full;\n            (void)hk;\n";
        for (int p = 0; p < static_cast<int>(r_.nodes.size()); ++p) {
            const std::string anchor = table + "[" + str(p) + "]";
            std::string cond = "area.searchesAt(h, full, hk, " + anchor + ")";
            if (const std::string kinds = hasEdgeKinds(match_.anchorEdgeKinds[static_cast<std::size_t>(p)], "h"); !kinds.empty())
                cond += " && " + kinds;
            out += "            if (" + cond + ") {\n";
            out += "                std::fill(std::begin(n), std::end(n), kNoId);\n                std::fill(std::begin(e), std::end(e), kNoId);\n"
                   "                std::fill(std::begin(f), std::end(f), kNoId);\n";
            out += "                n[" + str(p) + "] = h;\n";
            out += "                const EdgeId newFrom = area.newEdgesOnly(full, " + anchor + ");\n                (void)newFrom;\n";
            newEdgeGate_ = "newFrom != kNoId && !(" + bindsNewEdge("newFrom") + ")";
            std::string body;
            steps(match_.anchored[static_cast<std::size_t>(p)], 0, nullptr, "@@COMPLETE@@", body, "                ");
            newEdgeGate_.clear();
            const std::string first = p == 0 ? "" : " && area.firstAnchor(" + str(p) + ", n, e, " + str(static_cast<int>(r_.edges.size())) + ", " + table + ")";
            body.replace(body.find("@@COMPLETE@@"), 12, "if (" + nacTest + first + ") set.add(n, e, f, g);\n");
            out += body + "            }\n";
        }
        return out + "        }\n    }\n\n";
    }

    std::string nac(int k) {
        const auto& n = r_.nacs[k];
        std::string out = "    bool nac_" + ri_ + "_" + str(k) + "(const Graph& g, NodeId* n, EdgeId* e, FaceId* f) {\n        (void)e;\n        (void)f;\n";
        std::string body;
        steps(match_.negatives[static_cast<std::size_t>(k)], 0, &n, "@@COMPLETE@@", body, "        ");
        body.replace(body.find("@@COMPLETE@@"), 12, "return true;\n");
        return out + body + "        return false;\n    }\n\n";
    }

    std::string writeSet(int di, const lower::RewriteProgram& p) {
        std::string out = "    void writes_" + ri_ + "_" + str(di) + "(Match m, WriteSet& w) const {\n        (void)m;\n        (void)w;\n";
        for (int n : p.effects.writtenNodes) out += "        w.nodes.push_back(m.nodes[" + str(n) + "]);\n";
        for (int e : p.effects.writtenEdges) out += "        w.edges.push_back(m.edges[" + str(e) + "]);\n";
        for (int f : p.effects.writtenFaces) out += "        w.faces.push_back(m.faces[" + str(f) + "]);\n";
        return out + "    }\n\n";
    }

    // prepare_R_D prints the program's prepare part; apply_R_D its commit part.
    std::string prepare(int di, const lower::RewriteProgram& p) {
        auto reg = [](int r) { return RewritePrinter::reg(r); };
        const std::string in = "        ";
        const std::string rd = ri_ + "_" + str(di);
        std::string out = "    void prepare_" + rd + "(Match m, const Graph& g) {\n        (void)m;\n        (void)g;\n";
        ExprContext ctx;
        ctx.node = [](int i) { return "m.nodes[" + str(i) + "]"; };
        ctx.edge = [](int i) { return "m.edges[" + str(i) + "]"; };
        ctx.nodeKind = [this](int i) { return r_.nodes[i].kind; };
        ctx.edgeKind = [this](int i) { return r_.edges[i].kind; };
        ctx.face = [](int i) { return "m.faces[" + str(i) + "]"; };
        ctx.faceKind = [this](int i) { return r_.faces[static_cast<std::size_t>(i)].kind; };
        rewrite_.setLoopNames(rd);
        out += rewrite_.prepare(p, ctx, in);
        const std::string commit = rewrite_.commit(p, "        ");
        // Kept in a typed buffer until commit (no allocation once warm).
        const std::string nn = str(static_cast<int>(std::max<std::size_t>(r_.nodes.size(), 1)));
        const std::string ne = str(static_cast<int>(std::max<std::size_t>(r_.edges.size(), 1)));
        const std::string nf = str(static_cast<int>(std::max<std::size_t>(r_.faces.size(), 1)));
        std::string pending = "    struct Pending_" + rd + " {\n        NodeId mn[" + nn + "];\n        EdgeId me[" + ne + "];\n        FaceId mf[" + nf + "];\n";
        for (std::size_t r = 0; r < p.registers.size(); ++r) pending += "        " + cppType(p.registers[r]) + " " + reg(static_cast<int>(r)) + ";\n";
        for (std::size_t l = 0; l < p.loops.size(); ++l)
            pending += "        std::uint32_t loopFirst" + str(static_cast<int>(l)) + ", loopCount" + str(static_cast<int>(l)) + ";\n";
        // A parallel step keeps one per match: plain records grow without copying.
        pending += "    };\n    GrowableArray<Pending_" + rd + "> pending_" + rd + "_;\n\n";
        // A loop's turns: their corners and registers.
        for (std::size_t l = 0; l < p.loops.size(); ++l) {
            const std::string L = str(static_cast<int>(l));
            pending += "    struct Turn_" + rd + "_" + L + " {\n        NodeId u, v;\n";
            for (std::size_t r = 0; r < p.loops[l].registers.size(); ++r)
                pending += "        " + cppType(p.loops[l].registers[r]) + " " + RewritePrinter::loopReg(static_cast<int>(l), static_cast<int>(r)) + ";\n";
            pending += "    };\n    GrowableArray<Turn_" + rd + "_" + L + "> turns_" + rd + "_" + L + "_;\n\n";
        }
        out += in + "Pending_" + rd + "& p = pending_" + rd + "_.emplace_back();\n";
        out += in + "std::copy(m.nodes, m.nodes + " + str(static_cast<int>(r_.nodes.size())) + ", p.mn);\n";
        out += in + "std::copy(m.edges, m.edges + " + str(static_cast<int>(r_.edges.size())) + ", p.me);\n";
        if (!r_.faces.empty()) out += in + "std::copy(m.faces, m.faces + " + str(static_cast<int>(r_.faces.size())) + ", p.mf);\n";
        for (std::size_t r = 0; r < p.registers.size(); ++r) out += in + "p." + reg(static_cast<int>(r)) + " = " + reg(static_cast<int>(r)) + ";\n";
        for (std::size_t l = 0; l < p.loops.size(); ++l) {
            const std::string L = str(static_cast<int>(l));
            out += in + "p.loopFirst" + L + " = loopFirst" + L + ";\n" + in + "p.loopCount" + L + " = loopCount" + L + ";\n";
        }
        out += in + "pendingOrder_.push_back(PendingRef{" + str(firstDaughter_ + di) + ", static_cast<std::uint32_t>(pending_" + rd +
               "_.size() - 1)});\n";
        out += "    }\n\n";
        std::string apply = "    void apply_" + rd + "(Graph& G, long long step, const Pending_" + rd + "& p) {\n";
        apply += "        const Match m{p.mn, p.me, p.mf};\n        (void)m;\n";
        for (std::size_t r = 0; r < p.registers.size(); ++r)
            apply += "        const auto& " + reg(static_cast<int>(r)) + " = p." + reg(static_cast<int>(r)) + ";\n";
        return pending + out + apply + commit + "    }\n\n";
    }

    const ir::Program& prog_;
    const ir::Rule& r_;
    std::string ri_;
    int firstDaughter_;
    ExprGen& gen_;
    RewritePrinter rewrite_;
    const lower::MatchProgram& match_;
    // What the runtime knows of the rule, as its generic repair reads it
    // (RuleSet::repair): the inlined repair reads the same.
    const lower::RuleFacts& facts_;
    const std::vector<lower::RewriteProgram>& daughters_;
};

}  // namespace

std::string emitRule(const ir::Program& prog, const lower::LoweredRule& rule, int ruleIndex, int firstDaughter, ExprGen& gen,
                     Places& places, ConstantValues& constants) {
    return RuleEmitter(prog, rule, ruleIndex, firstDaughter, gen, places, constants).emit();
}

}  // namespace g2d::emit
