#include "g2d/element_scope.hpp"

#include <stdexcept>

namespace g2d::rt {

void ElementScope::addWithParts(const Graph& g, ElemClass c, std::uint32_t id) {
    add(c, id);
    if (c == ElemClass::Edge) {
        add(ElemClass::Node, g.source(id));
        add(ElemClass::Node, g.target(id));
    } else if (c == ElemClass::Face) {
        CornerId k = g.firstCorner(id);
        for (int i = 0; i < g.cornerCount(id); ++i, k = g.nextCorner(k)) {
            const NodeId u = g.cornerNode(k), v = g.cornerNode(g.nextCorner(k));
            add(ElemClass::Node, u);
            for (EdgeId e = g.firstOut(u); e != kNoId; e = g.nextOut(e))
                if (g.target(e) == v) add(ElemClass::Edge, e);
            for (EdgeId e = g.firstIn(u); e != kNoId; e = g.nextIn(e))
                if (g.source(e) == v) add(ElemClass::Edge, e);
        }
    }
}

const Value& compoundValue(const Graph& g, int compound, int slot) {
    for (const ElementScope* s = g.scope(); s; s = s->parent)
        if (s->compound == compound) return s->values.at(static_cast<std::size_t>(slot));
    throw std::logic_error("a compound's value was read outside the compound");
}

namespace scoped {

long long outDegree(const Graph& g, const ElementScope& s, NodeId n) {
    long long d = 0;
    for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e)) d += s.has(ElemClass::Edge, e);
    return d;
}

long long inDegree(const Graph& g, const ElementScope& s, NodeId n) {
    long long d = 0;
    for (EdgeId e = g.firstIn(n); e != kNoId; e = g.nextIn(e)) d += s.has(ElemClass::Edge, e);
    return d;
}

long long degree(const Graph& g, const ElementScope& s, NodeId n) {   // a self-loop counts once, as Graph::degree
    long long d = outDegree(g, s, n);
    for (EdgeId e = g.firstIn(n); e != kNoId; e = g.nextIn(e)) d += g.source(e) != n && s.has(ElemClass::Edge, e);
    return d;
}

long long facesAt(const Graph& g, const ElementScope& s, NodeId n) {
    long long count = 0;
    for (CornerId c = g.firstCornerAt(n); c != kNoId; c = g.nextCornerAt(c)) count += s.has(ElemClass::Face, g.cornerFace(c));
    return count;
}

long long sideFaces(const Graph& g, const ElementScope& s, NodeId u, NodeId v) {
    long long count = 0;
    g.eachSideUse(u, v, [&](FaceId f, bool) { count += s.has(ElemClass::Face, f); });
    return count;
}

long long neighbours(const Graph& g, const ElementScope& s, FaceId f) {
    std::vector<FaceId> all;
    g.neighbours(f, all);
    return std::count_if(all.begin(), all.end(), [&](FaceId h) { return s.has(ElemClass::Face, h); });
}

long long touching(const Graph& g, const ElementScope& s, FaceId f) {
    std::vector<FaceId> seen;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c))
        for (CornerId k = g.firstCornerAt(g.cornerNode(c)); k != kNoId; k = g.nextCornerAt(k)) {
            const FaceId h = g.cornerFace(k);
            if (h != f && s.has(ElemClass::Face, h) && std::find(seen.begin(), seen.end(), h) == seen.end()) seen.push_back(h);
        }
    return static_cast<long long>(seen.size());
}

}  // namespace scoped

}  // namespace g2d::rt
