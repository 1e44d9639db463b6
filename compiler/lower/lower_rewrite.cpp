#include <algorithm>

#include "lower/rewrite_program.hpp"

namespace g2d::lower {

namespace {

class RewriteLowering {
public:
    RewriteLowering(const ir::Program& prog, const ir::Rule& rule, const ir::Daughter& d)
        : prog_(prog), r_(rule), d_(d) {}

    RewriteProgram lower() {
        p_.nodeHandles = static_cast<int>(d_.nodes.size());
        p_.edgeHandles = static_cast<int>(d_.edges.size());
        p_.faceHandles = static_cast<int>(d_.faces.size() + d_.keptFaces.size() + d_.ringFaces.size());
        prepare();
        commit();
        return std::move(p_);
    }

private:
    int newRegister(ir::Type t) {
        p_.registers.push_back(t);
        return static_cast<int>(p_.registers.size() - 1);
    }
    // A literal is written as it is; anything else is evaluated by prepare.
    Operand operand(const ir::Expr& value) { return operandIn(value, p_.registers, p_.prepare); }
    static Operand operandIn(const ir::Expr& value, std::vector<ir::Type>& registers, std::vector<PrepareOp>& prepare) {
        if (value.op == ir::ExprOp::Literal) return Operand{-1, &value, value.type};
        registers.push_back(value.type);
        const int reg = static_cast<int>(registers.size() - 1);
        prepare.push_back(Eval{reg, &value});
        return Operand{reg, nullptr, value.type};
    }

    // A node a loop's turn or a split makes, on node handle `handle` at the
    // position in register posReg: its attributes, then radius, then styles.
    template <class OperandOf>
    static void createNode(const ir::LoopNode& n, int handle, int posReg, OperandOf& operand, std::vector<CommitOp>& out) {
        CreateNode c{handle, n.kind, posReg, {}};
        for (const auto& a : n.assigns) c.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
        out.push_back(std::move(c));
        if (n.radius) out.push_back(SetRadius{handle, operand(*n.radius)});
        for (const auto& st : n.styles) out.push_back(SetNodeStyle{handle, &st, operand(st.value)});
    }

    // A loop's turn, as its own little rewrite (LoopProgram): per turn, the
    // new nodes' positions, attributes and styles, then the edges', then
    // the faces', in order.
    LoopProgram lowerLoop(const ir::FaceLoop& l) const {
        LoopProgram lp;
        lp.matchFace = l.motherFace;
        lp.sides = l.sides;
        lp.firstVar = l.firstVar;
        lp.outerNodes = static_cast<int>(d_.nodes.size());
        lp.localNodes = static_cast<int>(l.nodes.size());
        const int H = lp.outerNodes, L = lp.localNodes;
        auto handle = [&](const ir::LoopNodeRef& r) {
            switch (r.scope) {
            case ir::LoopNodeRef::Scope::Daughter: return r.index;
            case ir::LoopNodeRef::Scope::Var: return H + r.index;
            case ir::LoopNodeRef::Scope::Local: return H + 2 + r.index;
            case ir::LoopNodeRef::Scope::Prev: return H + 2 + L + r.index;
            case ir::LoopNodeRef::Scope::Next: break;
            }
            return H + 2 + 2 * L + r.index;
        };
        auto operand = [&](const ir::Expr& v) { return operandIn(v, lp.registers, lp.prepare); };
        for (std::size_t i = 0; i < l.nodes.size(); ++i) {
            const auto& n = l.nodes[i];
            lp.registers.push_back(ir::positionType(prog_));
            const int pos = static_cast<int>(lp.registers.size() - 1);
            lp.prepare.push_back(EvalPosition{pos, &n.position, "position of `" + n.name + "` is not finite"});
            createNode(n, H + 2 + static_cast<int>(i), pos, operand, lp.create);
        }
        for (const auto& e : l.edges) {
            CreateEdge c{lp.edgeHandles, e.kind, handle(e.src), handle(e.dst), {}};
            for (const auto& a : e.assigns) c.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
            lp.link.push_back(std::move(c));
            for (const auto& st : e.styles) lp.link.push_back(SetEdgeStyle{lp.edgeHandles, &st, operand(st.value)});
            ++lp.edgeHandles;
        }
        for (const auto& f : l.faces) {
            CreateFace c{lp.faceHandles, f.kind, {}, {}, prog_.kinds[f.kind].oriented};
            for (const auto& r : f.corners) c.corners.push_back(handle(r));
            for (const auto& a : f.assigns) c.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
            lp.link.push_back(std::move(c));
            for (const auto& st : f.styles) lp.link.push_back(SetFaceStyle{lp.faceHandles, &st, operand(st.value), false});
            ++lp.faceHandles;
        }
        return lp;
    }

    // Everything is evaluated on the graph before the step, in the order the
    // grammar is written: the lets, automatic placement (which `at` may read
    // as `placed`), then per daughter node its position, attributes and
    // styles, then per daughter edge, then per new face, its attributes and
    // styles, then per kept face, then the loops (each turn in turn).
    void prepare() {
        for (const auto& l : r_.lets) p_.prepare.push_back(EvalLocal{l.slot, &l.value});
        for (const auto& l : d_.lets) p_.prepare.push_back(EvalLocal{l.slot, &l.value});
        if (d_.autoPlacement) place();
        posReg_.assign(d_.nodes.size(), -1);
        nodeAttrs_.resize(d_.nodes.size());
        nodeRadius_.resize(d_.nodes.size());
        nodeStyles_.resize(d_.nodes.size());
        for (std::size_t i = 0; i < d_.nodes.size(); ++i) {
            const auto& dn = d_.nodes[i];
            if (dn.position) {
                posReg_[i] = newRegister(ir::positionType(prog_));
                p_.prepare.push_back(EvalPosition{posReg_[i], &*dn.position, "position of `" + dn.name + "` is not finite"});
            } else if (dn.motherNode < 0) {
                posReg_[i] = newRegister(ir::positionType(prog_));
                p_.prepare.push_back(TakePlaced{posReg_[i], static_cast<int>(i)});
            }
            for (const auto& a : dn.assigns) nodeAttrs_[i].push_back(AttrWrite{a.attr, operand(a.value)});
            if (dn.radius) nodeRadius_[i] = operand(*dn.radius);
            for (const auto& s : dn.styles) nodeStyles_[i].emplace_back(&s, operand(s.value));
        }
        edgeAttrs_.resize(d_.edges.size());
        edgeStyles_.resize(d_.edges.size());
        for (std::size_t i = 0; i < d_.edges.size(); ++i) {
            for (const auto& a : d_.edges[i].assigns) edgeAttrs_[i].push_back(AttrWrite{a.attr, operand(a.value)});
            for (const auto& s : d_.edges[i].styles) edgeStyles_[i].emplace_back(&s, operand(s.value));
        }
        faceAttrs_.resize(d_.faces.size());
        faceStyles_.resize(d_.faces.size());
        for (std::size_t i = 0; i < d_.faces.size(); ++i) {
            for (const auto& a : d_.faces[i].assigns) faceAttrs_[i].push_back(AttrWrite{a.attr, operand(a.value)});
            for (const auto& s : d_.faces[i].styles) faceStyles_[i].emplace_back(&s, operand(s.value));
        }
        keptFaceAttrs_.resize(d_.keptFaces.size());
        keptFaceStyles_.resize(d_.keptFaces.size());
        for (std::size_t i = 0; i < d_.keptFaces.size(); ++i) {
            for (const auto& a : d_.keptFaces[i].assigns) keptFaceAttrs_[i].push_back(AttrWrite{a.attr, operand(a.value)});
            for (const auto& s : d_.keptFaces[i].styles) keptFaceStyles_[i].emplace_back(&s, operand(s.value));
        }
        ringAttrs_.resize(d_.ringFaces.size());
        ringStyles_.resize(d_.ringFaces.size());
        for (std::size_t i = 0; i < d_.loops.size(); ++i) {
            p_.loops.push_back(lowerLoop(d_.loops[i]));
            p_.prepare.push_back(PrepareLoop{static_cast<int>(i)});
            // A face over the loop's turns: its values once, after the turns'.
            for (std::size_t j = 0; j < d_.ringFaces.size(); ++j) {
                if (d_.ringFaces[j].loop != static_cast<int>(i)) continue;
                for (const auto& a : d_.ringFaces[j].assigns) ringAttrs_[j].push_back(AttrWrite{a.attr, operand(a.value)});
                for (const auto& s : d_.ringFaces[j].styles) ringStyles_[j].emplace_back(&s, operand(s.value));
            }
        }
        for (const auto& s : d_.splits) lowerSplit(s);
    }

    // A split: its centre's values and its edges' (once), then its corner loop.
    void lowerSplit(const ir::FaceSplit& s) {
        SplitProgram sp;
        sp.from = p_.nodeHandles++;
        sp.to = p_.nodeHandles++;
        sp.edgeHandle = p_.edgeHandles++;
        if (s.centre) {
            const int pos = newRegister(ir::positionType(prog_));
            p_.prepare.push_back(EvalPosition{pos, &s.centre->position, "position of the split's new node is not finite"});
            auto operandOf = [&](const ir::Expr& v) { return operand(v); };
            createNode(*s.centre, sp.to, pos, operandOf, sp.makeCentre);
        }
        CreateEdge e{sp.edgeHandle, s.edgeKind, sp.from, sp.to, {}};
        for (const auto& a : s.edgeAssigns) e.attrs.push_back(AttrWrite{a.attr, operand(a.value)});
        sp.makeEdge.push_back(std::move(e));
        for (const auto& st : s.edgeStyles) sp.makeEdge.push_back(SetEdgeStyle{sp.edgeHandle, &st, operand(st.value)});
        LoopProgram corners;
        corners.matchFace = s.motherFace;
        corners.sides = false;
        corners.firstVar = s.firstVar >= 0 ? s.firstVar : static_cast<int>(r_.nodes.size());
        corners.outerNodes = static_cast<int>(d_.nodes.size());
        if (s.cond) {
            corners.registers.push_back(ir::kBoolType);
            corners.prepare.push_back(Eval{0, &*s.cond});
            sp.chosenReg = 0;
        }
        sp.loop = static_cast<int>(p_.loops.size());
        p_.prepare.push_back(PrepareLoop{sp.loop});
        p_.loops.push_back(std::move(corners));
        p_.splits.push_back(std::move(sp));
    }

    void place() {
        Place pl;
        // A face's hidden anchor has no sketch and is no reference; a
        // wildcard without one takes no part (sema allows only those).
        std::vector<int> memberOf(r_.nodes.size(), -1);
        for (std::size_t i = 0; i < r_.nodes.size(); ++i) {
            const auto& n = r_.nodes[i];
            if (!n.sketch && n.anchorOf < 0 && n.kind < 0) continue;
            memberOf[i] = static_cast<int>(pl.members.size());
            pl.members.push_back(static_cast<int>(i));
            pl.motherSketch.push_back(n.sketch.value_or(ir::Vec2{0, 0}));
        }
        for (const auto& dn : d_.nodes)
            if (dn.motherNode >= 0 && dn.sketch) pl.refs.emplace_back(*dn.sketch, dn.motherNode);
        // No node kept: the whole match is the reference.
        if (pl.refs.empty())
            for (std::size_t i = 0; i < r_.nodes.size(); ++i)
                if (r_.nodes[i].sketch) pl.refs.emplace_back(*r_.nodes[i].sketch, static_cast<int>(i));
        for (const auto& e : r_.edges)
            if (prog_.kinds[e.kind].directed && e.src != e.dst && memberOf[e.src] >= 0 && memberOf[e.dst] >= 0) {
                pl.directed = std::make_pair(memberOf[e.src], memberOf[e.dst]);
                break;
            }
        for (std::size_t i = 0; i < d_.nodes.size(); ++i) {
            const auto& dn = d_.nodes[i];
            if (dn.motherNode >= 0 || !dn.sketch) continue;
            pl.targets.push_back(Place::Target{static_cast<int>(i), *dn.sketch, dn.span,
                                               "automatic placement of `" + dn.name + "` gives a non-finite position"});
        }
        pl.space3d = prog_.space3d;
        p_.prepare.push_back(std::move(pl));
        p_.placement = true;
    }

    bool rewired(const ir::DaughterEdge& de) const { return ir::keptEdgeRewired(r_, d_, de); }

    // The order of the updates: deleted faces and edges go; new nodes come;
    // kept edges that change ends are reconnected (before their old end
    // nodes go, so they survive); deleted nodes go with their remaining edges
    // and faces; then kept nodes change, and edges are updated or created, in
    // the daughter's order; then `insert`s put nodes into existing faces; then
    // kept faces change, and new faces come.
    void commit() {
        auto& c = p_.commit;
        for (int f : d_.deletedFaces) c.push_back(DeleteFace{f});
        for (int e : d_.deletedEdges) c.push_back(DeleteEdge{e});
        for (std::size_t i = 0; i < d_.nodes.size(); ++i) {
            const auto& dn = d_.nodes[i];
            const int h = static_cast<int>(i);
            if (dn.motherNode >= 0) c.push_back(BindNode{h, dn.motherNode});
            else c.push_back(CreateNode{h, dn.kind, posReg_[i], nodeAttrs_[i]});
        }
        for (const auto& de : d_.edges)
            if (de.motherEdge >= 0 && rewired(de)) c.push_back(Rewire{de.motherEdge, de.src, de.dst, de.kind});
        for (int n : d_.deletedNodes) c.push_back(DeleteNode{n});
        for (std::size_t i = 0; i < d_.nodes.size(); ++i) {
            const auto& dn = d_.nodes[i];
            const int h = static_cast<int>(i);
            if (dn.motherNode >= 0) {
                if (dn.position) c.push_back(SetPos{h, posReg_[i]});
                for (const auto& w : nodeAttrs_[i]) c.push_back(SetNodeAttr{h, dn.kind, w});
                // Attributes live outside the graph's records: tell it, for incremental matching.
                if (!nodeAttrs_[i].empty()) c.push_back(TouchNodeValues{h});
            }
            if (nodeRadius_[i]) c.push_back(SetRadius{h, *nodeRadius_[i]});
            for (const auto& [style, value] : nodeStyles_[i]) c.push_back(SetNodeStyle{h, style, value});
        }
        for (std::size_t i = 0; i < d_.edges.size(); ++i) {
            const auto& de = d_.edges[i];
            const int h = static_cast<int>(i);
            if (de.motherEdge >= 0) {
                c.push_back(BindEdge{h, de.motherEdge});
                for (const auto& w : edgeAttrs_[i]) c.push_back(SetEdgeAttr{h, de.kind, w});
                if (!edgeAttrs_[i].empty()) c.push_back(TouchEdge{h});
            } else {
                c.push_back(CreateEdge{h, de.kind, de.src, de.dst, edgeAttrs_[i]});
            }
            for (const auto& [style, value] : edgeStyles_[i]) c.push_back(SetEdgeStyle{h, style, value});
        }
        // Existing faces (kept ones included) grow corners; new faces are as written.
        for (const auto& ins : d_.inserts) c.push_back(InsertBetween{ins.node, ins.first, ins.second});
        for (std::size_t i = 0; i < d_.keptFaces.size(); ++i) {
            const auto& kf = d_.keptFaces[i];
            const int h = static_cast<int>(d_.faces.size() + i);
            c.push_back(BindFace{h, kf.motherFace});
            for (const auto& w : keptFaceAttrs_[i]) c.push_back(SetFaceAttr{h, r_.faces[kf.motherFace].kind, w, true});
            if (!keptFaceAttrs_[i].empty()) c.push_back(TouchFace{h, true});
            for (const auto& [style, value] : keptFaceStyles_[i]) c.push_back(SetFaceStyle{h, style, value, true});
        }
        for (std::size_t i = 0; i < d_.faces.size(); ++i) {
            const auto& df = d_.faces[i];
            const int h = static_cast<int>(i);
            c.push_back(CreateFace{h, df.kind, df.corners, faceAttrs_[i], prog_.kinds[df.kind].oriented});
            for (const auto& [style, value] : faceStyles_[i]) c.push_back(SetFaceStyle{h, style, value, false});
        }
        for (std::size_t i = 0; i < d_.loops.size(); ++i) {
            c.push_back(CommitLoop{static_cast<int>(i)});
            // Right after its loop, while the back ends hold the turns' nodes.
            for (std::size_t j = 0; j < d_.ringFaces.size(); ++j) {
                const ir::RingFace& rf = d_.ringFaces[j];
                if (rf.loop != static_cast<int>(i)) continue;
                const int h = static_cast<int>(d_.faces.size() + d_.keptFaces.size() + j);
                const int turnNode = rf.corner.scope == ir::LoopNodeRef::Scope::Var ? rf.corner.index : 2 + rf.corner.index;
                c.push_back(CreateRingFace{h, rf.kind, static_cast<int>(i), turnNode, rf.reversed, ringAttrs_[j], prog_.kinds[rf.kind].oriented});
                for (const auto& [style, value] : ringStyles_[j]) c.push_back(SetFaceStyle{h, style, value, false});
            }
        }
        // Last, so the face has its attributes (and any inserted corners) when it is cut.
        for (std::size_t i = 0; i < d_.splits.size(); ++i) c.push_back(SplitFace{keptFaceHandle(d_.splits[i].motherFace), static_cast<int>(i)});
        p_.effects = rewriteEffects(prog_, r_, p_);
    }

    int keptFaceHandle(int motherFace) const {
        for (std::size_t i = 0; i < d_.keptFaces.size(); ++i)
            if (d_.keptFaces[i].motherFace == motherFace) return static_cast<int>(d_.faces.size() + i);
        return -1;
    }

    const ir::Program& prog_;
    const ir::Rule& r_;
    const ir::Daughter& d_;
    RewriteProgram p_;
    std::vector<int> posReg_;
    std::vector<std::vector<AttrWrite>> nodeAttrs_, edgeAttrs_, faceAttrs_, keptFaceAttrs_, ringAttrs_;
    std::vector<std::optional<Operand>> nodeRadius_;
    std::vector<std::vector<std::pair<const ir::StyleAssign*, Operand>>> nodeStyles_, edgeStyles_, faceStyles_, keptFaceStyles_, ringStyles_;
};

}  // namespace

RewriteProgram lowerRewrite(const ir::Program& prog, const ir::Rule& rule, std::size_t daughter) {
    return RewriteLowering(prog, rule, rule.daughters.at(daughter)).lower();
}

}  // namespace g2d::lower
