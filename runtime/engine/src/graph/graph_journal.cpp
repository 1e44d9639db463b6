// Undoing one application (graph_journal.hpp): the recorded changes are
// reverted newest first, each after removing the elements made after it,
// so every list threaded through the records is relinked where it was
// (dancing links: a record taken out keeps its neighbours).
#include <stdexcept>

#include "g2d/graph.hpp"

namespace g2d::rt {

void Graph::beginJournal(GraphJournal& j) {
    j.from = capacities();
    j.entries.clear();
    j.lost = false;
    journal_ = &j;
}

void Graph::journalNode(NodeId n) {
    if (n >= journal_->from[0]) return;   // a new node goes with the rest
    GraphJournal::Entry e{GraphJournal::Op::Node, n, capacities()};
    e.pos = nodes_[n].pos;
    e.z = z(n);
    e.radius = radius(n);
    journal_->entries.push_back(e);
}

void Graph::journalEdge(EdgeId e) {
    if (e >= journal_->from[1]) return;
    const EdgeRec& r = edges_[e];
    GraphJournal::Entry entry{GraphJournal::Op::Edge, e, capacities()};
    entry.links = {r.src, r.dst, r.prevOut, r.nextOut, r.prevIn, r.nextIn};
    journal_->entries.push_back(entry);
}

void Graph::endJournal(bool undo) {
    GraphJournal* j = journal_;
    journal_ = nullptr;
    if (!j) return;
    if (!undo) {
        // Kept: the removed faces' attributes and styles go now.
        for (const auto& e : j->entries)
            if (e.op == GraphJournal::Op::FaceRemoved) {
                FaceRec& rec = faces_[e.id];
                clearAttrBlock(rec.kind, rec.slot);
                if (rec.marks & kStyled) styles_.drop(faceStyleList_[e.id]);
                rec.marks &= static_cast<std::uint8_t>(~kStyled);
            }
        return;
    }
    if (j->lost) throw std::logic_error("an application to be undone deleted or reshaped an older element (internal error)");
    for (std::size_t k = j->entries.size(); k-- > 0;) {
        removeNewSince(j->entries[k].at);
        revert(j->entries[k]);
    }
    removeNewSince(j->from);
    j->entries.clear();
}

void Graph::removeNewSince(const GraphJournal::Capacities& at) {
    // Newest first: each then leaves its kind's index from the end.
    for (std::size_t f = faces_.size(); f-- > at[2];)
        if (faces_[f].alive) removeFace(static_cast<FaceId>(f));
    for (std::size_t e = edges_.size(); e-- > at[1];)
        if (edges_[e].alive) removeEdge(static_cast<EdgeId>(e));
    for (std::size_t n = nodes_.size(); n-- > at[0];)
        if (nodes_[n].alive) removeNode(static_cast<NodeId>(n));
}

void Graph::revert(const GraphJournal::Entry& entry) {
    switch (entry.op) {
    case GraphJournal::Op::Node:
        setZ(entry.id, entry.z);
        setPos(entry.id, entry.pos);
        setRadius(entry.id, entry.radius);
        break;
    case GraphJournal::Op::Edge: {
        const EdgeId e = entry.id;
        touchEdgeItself(e);
        unlink(e);   // at the heads of its lists: everything linked after it is undone
        EdgeRec& rec = edges_[e];
        const auto& l = entry.links;
        rec.src = l[0];
        rec.dst = l[1];
        rec.prevOut = l[2];
        rec.nextOut = l[3];
        rec.prevIn = l[4];
        rec.nextIn = l[5];
        (rec.prevOut != kNoId ? edges_[rec.prevOut].nextOut : nodes_[rec.src].firstOut) = e;
        if (rec.nextOut != kNoId) edges_[rec.nextOut].prevOut = e;
        (rec.prevIn != kNoId ? edges_[rec.prevIn].nextIn : nodes_[rec.dst].firstIn) = e;
        if (rec.nextIn != kNoId) edges_[rec.nextIn].prevIn = e;
        touchEdgeItself(e);
        break;
    }
    case GraphJournal::Op::Corner: {
        const FaceId f = corners_[entry.id].face;
        if (!faces_[f].alive) break;   // a new face, gone already
        removeCorner(entry.id);
        faceReshaped(f);
        break;
    }
    case GraphJournal::Op::FaceRemoved:
        reviveFace(entry.id);
        break;
    }
}

void Graph::reviveFace(FaceId f) {
    FaceRec& rec = faces_[f];
    // Back to its place in its kind's index, the face that took it to the end.
    auto& kindList = kindNodes_[rec.kind];
    if (rec.slotInKind == kindList.size()) {
        kindList.push_back(f);
    } else {
        const std::uint32_t moved = kindList[rec.slotInKind];
        faces_[moved].slotInKind = static_cast<std::uint32_t>(kindList.size());
        kindList.push_back(moved);
        kindList[rec.slotInKind] = f;
    }
    rec.alive = true;
    ++liveFaces_;
    // Its corners back at their nodes, the reverse of removeFace's order.
    std::vector<CornerId> cycle;
    CornerId c = rec.firstCorner;
    for (std::uint32_t i = 0; i < rec.cornerCount; ++i, c = corners_[c].next) cycle.push_back(c);
    for (std::size_t i = cycle.size(); i-- > 0;) {
        CornerRec& cr = corners_[cycle[i]];
        NodeCorners& at = nodeCorners_[cr.node];
        (cr.prevAtNode != kNoId ? corners_[cr.prevAtNode].nextAtNode : at.first) = cycle[i];
        if (cr.nextAtNode != kNoId) corners_[cr.nextAtNode].prevAtNode = cycle[i];
        ++at.count;
        touchNode(cr.node);
    }
    touchFace(f);
    if (trackNeighbours_) touchNeighbourAnchors(f);
}

}  // namespace g2d::rt
