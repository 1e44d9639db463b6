#include "lower/rewrite_effects.hpp"

#include <set>

#include "lower/kind_set.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::lower {

namespace {

class EffectsVisit {
public:
    EffectsVisit(const ir::Program& prog, const ir::Rule& rule, const RewriteProgram& p)
        : rule_(rule), p_(p), changed_(prog.kinds), node_(static_cast<std::size_t>(p.nodeHandles)),
          edge_(static_cast<std::size_t>(p.edgeHandles)), face_(static_cast<std::size_t>(p.faceHandles)) {}

    RewriteEffects run() {
        for (const auto& op : p_.commit) visit(op, nullptr);
        out_.changedKinds = changed_.sorted();
        out_.changedValues.assign(values_.begin(), values_.end());
        // After the deletions (which the visit listed): a split face, then
        // the kept elements in handle (= the daughter's) order.
        out_.writtenFaces.insert(out_.writtenFaces.end(), splitFaces_.begin(), splitFaces_.end());
        for (const Slot& n : node_)
            if (n.mother >= 0 && n.written) out_.writtenNodes.push_back(n.mother);
        for (const Slot& e : edge_)
            if (e.mother >= 0 && e.written) out_.writtenEdges.push_back(e.mother);
        for (const Slot& f : face_)
            if (f.mother >= 0 && f.written) out_.writtenFaces.push_back(f.mother);
        for (const Slot& e : edge_)
            if (e.drawnNew) out_.shape.newEdges.push_back(e.drawn);
        return std::move(out_);
    }

private:
    // A handle of the daughter: a pattern element it keeps (mother >= 0) or
    // one it makes (kind).
    struct Slot {
        int mother = -1, kind = -1, shapeEnd = 0;
        bool written = false;
        bool drawnNew = false;              // an edge the drawing sees made (new, or kept with new ends)
        rt::DaughterShape::NewEdge drawn;
    };

    int nodeKind(int matchNode) const { return rule_.nodes[static_cast<std::size_t>(matchNode)].kind; }
    int edgeKind(int matchEdge) const { return rule_.edges[static_cast<std::size_t>(matchEdge)].kind; }
    int faceKind(int matchFace) const { return rule_.faces[static_cast<std::size_t>(matchFace)].kind; }

    // The daughter's node slot of a handle, or null for a loop turn's own
    // nodes (new ones, or the turn's corners, which it does not change).
    Slot* nodeSlot(int handle, const LoopProgram* loop) {
        if (loop && handle >= loop->outerNodes) return nullptr;
        return &node_[static_cast<std::size_t>(handle)];
    }
    Slot* edgeSlot(int handle, const LoopProgram* loop) { return loop ? nullptr : &edge_[static_cast<std::size_t>(handle)]; }
    Slot* faceSlot(int handle, const LoopProgram* loop) { return loop ? nullptr : &face_[static_cast<std::size_t>(handle)]; }

    // A kept node's position or radius: a change of its kind.
    void moved(Slot* n) {
        if (!n || n->mother < 0) return;
        n->written = true;
        changed_.add(nodeKind(n->mother), ir::ElemClass::Node);
    }
    void styled(Slot* s) {
        if (s && s->mother >= 0) s->written = true;
    }
    int kindOf(Slot* n) const { return !n ? -1 : n->mother >= 0 ? nodeKind(n->mother) : n->kind; }

    void visitAll(const std::vector<CommitOp>& ops, const LoopProgram* loop) {
        for (const auto& op : ops) visit(op, loop);
    }

    void visit(const CommitOp& op, const LoopProgram* loop) {
        std::visit(Overloaded{
                       [&](const DeleteFace& o) {
                           changed_.add(faceKind(o.matchFace), ir::ElemClass::Face);
                           out_.writtenFaces.push_back(o.matchFace);
                       },
                       [&](const DeleteEdge& o) {
                           changed_.add(edgeKind(o.matchEdge), ir::ElemClass::Edge);
                           out_.writtenEdges.push_back(o.matchEdge);
                           out_.shape.deletedEdges.push_back(o.matchEdge);
                       },
                       [&](const BindNode& o) {
                           if (Slot* n = nodeSlot(o.handle, loop)) n->mother = o.matchNode, n->shapeEnd = o.matchNode;
                       },
                       [&](const CreateNode& o) {
                           changed_.add(o.kind, ir::ElemClass::Node);
                           if (Slot* n = nodeSlot(o.handle, loop)) n->kind = o.kind;
                           if (loop || inSplit_) return;
                           node_[static_cast<std::size_t>(o.handle)].shapeEnd = -1 - out_.shape.newNodes++;
                           out_.shape.newNodeKinds.push_back(o.kind);
                       },
                       [&](const Rewire& o) {
                           changed_.add(edgeKind(o.matchEdge), ir::ElemClass::Edge);
                           out_.shape.deletedEdges.push_back(o.matchEdge);
                           rewires_.push_back(o);
                       },
                       [&](const DeleteNode& o) {
                           changed_.add(nodeKind(o.matchNode), ir::ElemClass::Node);
                           out_.writtenNodes.push_back(o.matchNode);
                           out_.shape.deletedNodes.push_back(o.matchNode);
                           out_.deletesNodes = true;
                       },
                       [&](const SetPos& o) { moved(nodeSlot(o.handle, loop)); },
                       [&](const SetRadius& o) { moved(nodeSlot(o.handle, loop)); },
                       [&](const SetNodeAttr& o) {
                           Slot* n = nodeSlot(o.handle, loop);
                           if (!n || n->mother < 0) return;
                           n->written = true;
                           values_.insert(valueKey(o.kind, o.write.attr));
                       },
                       [&](const TouchNodeValues& o) { styled(nodeSlot(o.handle, loop)); },
                       [&](const SetNodeStyle& o) { styled(nodeSlot(o.handle, loop)); },
                       [&](const BindEdge& o) { bindEdge(o, loop); },
                       [&](const SetEdgeAttr& o) { edgeChanged(edgeSlot(o.handle, loop)); },
                       [&](const TouchEdge& o) { edgeChanged(edgeSlot(o.handle, loop)); },
                       [&](const CreateEdge& o) {
                           changed_.add(o.kind, ir::ElemClass::Edge);
                           Slot* e = edgeSlot(o.handle, loop);
                           if (!e) return;
                           e->kind = o.kind;
                           if (!inSplit_) drawNew(*e, o.src, o.dst, o.kind);
                       },
                       [&](const SetEdgeStyle& o) { styled(edgeSlot(o.handle, loop)); },
                       [&](const BindFace& o) {
                           if (Slot* f = faceSlot(o.handle, loop)) f->mother = o.matchFace;
                       },
                       [&](const SetFaceAttr& o) {
                           Slot* f = faceSlot(o.handle, loop);
                           if (!f || f->mother < 0) return;
                           f->written = true;
                           if (o.kind >= 0) values_.insert(valueKey(o.kind, o.write.attr));
                       },
                       [&](const TouchFace& o) { styled(faceSlot(o.handle, loop)); },
                       [&](const CreateFace& o) { changed_.add(o.kind, ir::ElemClass::Face); },
                       [&](const SetFaceStyle& o) { styled(faceSlot(o.handle, loop)); },
                       [&](const InsertBetween& o) {   // faces of any kind grow a corner
                           changed_.add(-1, ir::ElemClass::Face);
                           for (int h : {o.node, o.first, o.second}) changed_.add(kindOf(nodeSlot(h, loop)), ir::ElemClass::Node);
                       },
                       [&](const CommitLoop& o) {
                           const LoopProgram& l = p_.loops[static_cast<std::size_t>(o.loop)];
                           visitAll(l.create, &l);
                           visitAll(l.link, &l);
                       },
                       [&](const CreateRingFace& o) { changed_.add(o.kind, ir::ElemClass::Face); },
                       [&](const SplitFace& o) { split(o); },
                   },
                   op);
    }

    void bindEdge(const BindEdge& o, const LoopProgram* loop) {
        Slot* e = edgeSlot(o.handle, loop);
        if (!e) return;
        e->mother = o.matchEdge;
        for (const Rewire& r : rewires_)
            if (r.matchEdge == o.matchEdge) {
                e->written = true;
                drawNew(*e, r.src, r.dst, r.kind);
            }
    }

    void drawNew(Slot& e, int src, int dst, int kind) {
        e.drawnNew = true;
        e.drawn = {node_[static_cast<std::size_t>(src)].shapeEnd, node_[static_cast<std::size_t>(dst)].shapeEnd, kind};
    }

    // A kept edge's attributes: a change of its kind.
    void edgeChanged(Slot* e) {
        if (!e || e->mother < 0) return;
        e->written = true;
        changed_.add(edgeKind(e->mother), ir::ElemClass::Edge);
    }

    // The face is replaced by its pieces; the new edges' corners, of any
    // kind, gain an edge.
    void split(const SplitFace& o) {
        const SplitProgram& sp = p_.splits[static_cast<std::size_t>(o.split)];
        const int motherFace = p_.loops[static_cast<std::size_t>(sp.loop)].matchFace;
        inSplit_ = true;
        visitAll(sp.makeCentre, nullptr);
        visitAll(sp.makeEdge, nullptr);
        inSplit_ = false;
        changed_.add(faceKind(motherFace), ir::ElemClass::Face);
        changed_.add(-1, ir::ElemClass::Node);
        splitFaces_.push_back(motherFace);
    }

    const ir::Rule& rule_;
    const RewriteProgram& p_;
    KindSet changed_;
    std::set<long long> values_;
    std::vector<Slot> node_, edge_, face_;
    std::vector<Rewire> rewires_;
    std::vector<int> splitFaces_;
    RewriteEffects out_;
    // A split's own elements: how many it makes depends on the face, so the
    // drawing's shape (which sema keeps splits away from) leaves them out.
    bool inSplit_ = false;
};

}  // namespace

RewriteEffects rewriteEffects(const ir::Program& prog, const ir::Rule& rule, const RewriteProgram& program) {
    return EffectsVisit(prog, rule, program).run();
}

}  // namespace g2d::lower
