#include "g2d/graph_view.hpp"

#include "g2d/graph.hpp"

namespace g2d {

using rt::ElemClass;

std::size_t GraphView::count(ElemClass cls) const {
    switch (cls) {
        case ElemClass::Node: return graph_->nodeCount();
        case ElemClass::Edge: return graph_->edgeCount();
        case ElemClass::Face: return graph_->faceCount();
    }
    return 0;
}

std::size_t GraphView::capacity(ElemClass cls) const {
    switch (cls) {
        case ElemClass::Node: return graph_->nodeCapacity();
        case ElemClass::Edge: return graph_->edgeCapacity();
        case ElemClass::Face: return graph_->faceCapacity();
    }
    return 0;
}

bool GraphView::alive(ElemClass cls, Id id) const {
    switch (cls) {
        case ElemClass::Node: return graph_->nodeAlive(id);
        case ElemClass::Edge: return graph_->edgeAlive(id);
        case ElemClass::Face: return graph_->faceAlive(id);
    }
    return false;
}

int GraphView::kind(ElemClass cls, Id id) const { return graph_->kindOf(cls, id); }

const std::string& GraphView::kindName(ElemClass cls, Id id) const {
    return kindNames_->at(static_cast<std::size_t>(kind(cls, id)));
}

rt::vec3 GraphView::position(Id node) const { return graph_->pos3(node); }
GraphView::Id GraphView::source(Id edge) const { return graph_->source(edge); }
GraphView::Id GraphView::target(Id edge) const { return graph_->target(edge); }

std::vector<GraphView::Id> GraphView::corners(Id face) const {
    std::vector<Id> out;
    rt::CornerId c = graph_->firstCorner(face);
    for (int i = 0; i < graph_->cornerCount(face); ++i, c = graph_->nextCorner(c)) out.push_back(graph_->cornerNode(c));
    return out;
}

}  // namespace g2d
