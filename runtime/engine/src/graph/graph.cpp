#include "g2d/graph.hpp"

#include <algorithm>
#include <stdexcept>

namespace g2d::rt {

IncidentRange::iterator IncidentRange::begin() const {
    return iterator(g_, n_, g_->firstOut(n_), false);
}

void IncidentRange::iterator::settle() {
    // Out of outgoing edges: continue with incoming ones, skipping self-loops
    // (already seen among the outgoing).
    while (true) {
        if (e_ == kNoId) {
            if (in_) return;
            in_ = true;
            e_ = g_->firstIn(n_);
            continue;
        }
        if (in_ && g_->source(e_) == n_) {
            e_ = g_->nextIn(e_);
            continue;
        }
        return;
    }
}

IncidentRange::iterator& IncidentRange::iterator::operator++() {
    e_ = in_ ? g_->nextIn(e_) : g_->nextOut(e_);
    settle();
    return *this;
}

Graph::Graph(std::vector<KindInfo> kinds, std::vector<std::string> styleProps)
    : kinds_(std::move(kinds)), defaults_(kinds_.size()), pool_(kinds_.size()), kindNodes_(kinds_.size()),
      styles_(std::move(styleProps)) {
    if (kinds_.size() > kMaxKinds) throw std::length_error("a grammar may declare at most 32767 kinds");
    // The two columns every graph grows: each in its own mapping from the
    // start (grow_array.hpp), so that they never copy themselves, and a
    // page is first touched only when a record reaches it (a chain of
    // reallocations copied each into fresh pages). Other arrays start small,
    // to share pages.
    nodes_.reserve(grow_detail::kOwnMappingBytes / sizeof(NodeRec) + 1);
    edges_.reserve(grow_detail::kOwnMappingBytes / sizeof(EdgeRec) + 1);
}

void Graph::setKindDefaults(int kind, std::vector<Value> defaults) {
    anyPooled_ = anyPooled_ || !defaults.empty();
    defaults_[kind] = std::move(defaults);
}

std::uint32_t Graph::newAttrBlock(int kind, std::vector<Value>* attrs) {
    const auto& defaults = defaults_[kind];
    if (defaults.empty()) return kNoId;
    auto& pool = pool_[kind];
    const auto slot = static_cast<std::uint32_t>(pool.size() / defaults.size());
    if (attrs && attrs->size() == defaults.size())
        for (auto& v : *attrs) pool.push_back(std::move(v));
    else
        pool.insert(pool.end(), defaults.begin(), defaults.end());
    return slot;
}

void Graph::clearAttrBlock(int kind, std::uint32_t slot) {
    // Ids are never reused, so neither are blocks; only free what values own.
    if (slot == kNoId || !pooled(kind)) return;
    for (std::size_t i = 0; i < defaults_[kind].size(); ++i) pool_[kind][attrIndex(kind, slot, static_cast<int>(i))] = Value{};
}

NodeId Graph::addNode(int kind, vec2 pos, long long age, std::vector<Value> attrs) {
    const NodeId id = addNode(kind, pos, age);
    for (std::size_t i = 0; i < attrs.size() && i < defaults_[kind].size(); ++i)
        pool_[kind][attrIndex(kind, nodes_[id].slot, static_cast<int>(i))] = std::move(attrs[i]);
    return id;
}

EdgeId Graph::addEdge(int kind, NodeId src, NodeId dst, long long age, std::vector<Value> attrs) {
    const EdgeId id = addEdge(kind, src, dst, age);
    for (std::size_t i = 0; i < attrs.size() && i < defaults_[kind].size(); ++i)
        pool_[kind][attrIndex(kind, edges_[id].slot, static_cast<int>(i))] = std::move(attrs[i]);
    return id;
}

void Graph::deadEndpoint() { throw std::logic_error("edge endpoint is not a live node"); }

void Graph::dropEdgeExtras(EdgeRec& rec, EdgeId e) {
    clearAttrBlock(rec.kind, rec.slot);
    if (rec.styled) styles_.drop(edgeStyleList_[e]);
    rec.styled = false;
}

void Graph::removeNode(NodeId n) {
    auto& rec = nodes_[n];
    if (!rec.alive) return;
    if (journal_ && n < journal_->from[0]) journal_->lost = true;
    touchNode(n);
    removeFacesAt(n);
    while (rec.firstOut != kNoId) removeEdge(rec.firstOut);
    while (rec.firstIn != kNoId) removeEdge(rec.firstIn);
    retire(rec, nodes_, nodeStyleList_, n);
    --liveNodes_;
}

void Graph::reconnectEdge(EdgeId e, NodeId src, NodeId dst) {
    auto& rec = edges_[e];
    if (!rec.alive || !nodeAlive(src) || !nodeAlive(dst)) throw std::logic_error("reconnecting a dead edge or to a dead node");
    if (rec.src == src && rec.dst == dst) return;
    if (journal_) journalEdge(e);
    touchEdgeItself(e);
    unlink(e);
    rec.src = src;
    rec.dst = dst;
    link(e);
    touchEdgeItself(e);
}

void Graph::setNodeAttr(NodeId n, int i, Value v) {
    initNodeAttr(n, i, std::move(v));
    touchNodeValues(n);
}

void Graph::initNodeAttr(NodeId n, int i, Value v) {
    pool_[nodes_[n].kind][attrIndex(nodes_[n].kind, nodes_[n].slot, i)] = std::move(v);
}

void Graph::setEdgeAttr(EdgeId e, int i, Value v) {
    initEdgeAttr(e, i, std::move(v));
    touchEdgeItself(e);
}

void Graph::initEdgeAttr(EdgeId e, int i, Value v) {
    pool_[edges_[e].kind][attrIndex(edges_[e].kind, edges_[e].slot, i)] = std::move(v);
}

StyleList Graph::nodeStyle(NodeId n) const {
    return styles_.list((nodes_[n].marks & kStyled) ? nodeStyleList_[n] : StyleStore::kNone);
}

StyleList Graph::edgeStyle(EdgeId e) const {
    return styles_.list(edges_[e].styled ? edgeStyleList_[e] : StyleStore::kNone);
}

void Graph::setNodeStyle(NodeId n, StyleProp prop, Value&& v) {
    nodes_[n].marks |= kStyled;
    styles_.set(styleHead(nodeStyleList_, n, nodes_.size()), prop, std::move(v));
}

void Graph::setNodeStyle(NodeId n, StyleProp prop, const Value& v) {
    nodes_[n].marks |= kStyled;
    styles_.set(styleHead(nodeStyleList_, n, nodes_.size()), prop, v);
}

void Graph::setEdgeStyle(EdgeId e, StyleProp prop, Value&& v) {
    edges_[e].styled = true;
    styles_.set(styleHead(edgeStyleList_, e, edges_.size()), prop, std::move(v));
}

void Graph::setEdgeStyle(EdgeId e, StyleProp prop, const Value& v) {
    edges_[e].styled = true;
    styles_.set(styleHead(edgeStyleList_, e, edges_.size()), prop, v);
}

void Graph::forgetChanges() {
    for (NodeId n : dirty_) nodes_[n].marks &= static_cast<std::uint8_t>(~kChanged);
    dirty_.clear();
    for (FaceId f : dirtyFaces_) faces_[f].marks &= static_cast<std::uint8_t>(~kFaceChanged);
    dirtyFaces_.clear();
    valuesWritten_ = false;
}

int Graph::degree(NodeId n) const {
    int d = 0;
    for (EdgeId e = firstOut(n); e != kNoId; e = nextOut(e)) ++d;
    for (EdgeId e = firstIn(n); e != kNoId; e = nextIn(e)) d += edges_[e].src != n;
    return d;
}

int Graph::inDegree(NodeId n) const {
    int d = 0;
    for (EdgeId e = firstIn(n); e != kNoId; e = nextIn(e)) ++d;
    return d;
}

int Graph::outDegree(NodeId n) const {
    int d = 0;
    for (EdgeId e = firstOut(n); e != kNoId; e = nextOut(e)) ++d;
    return d;
}

namespace {
// Ids [from, capacity) of one class get `generation`; a column stays empty
// while every generation is 0.
void setGenerations(std::vector<long long>& column, std::size_t from, std::size_t capacity, long long generation) {
    if (from >= capacity || (generation == 0 && column.size() <= from)) return;
    if (column.size() < capacity) column.resize(capacity, 0);
    std::fill(column.begin() + static_cast<std::ptrdiff_t>(from), column.begin() + static_cast<std::ptrdiff_t>(capacity), generation);
}
}  // namespace

void Graph::setGenerationsFrom(NodeId nodesFrom, EdgeId edgesFrom, FaceId facesFrom, long long generation) {
    setGenerations(nodeGen_, nodesFrom, nodes_.size(), generation);
    setGenerations(edgeGen_, edgesFrom, edges_.size(), generation);
    setGenerations(faceGen_, facesFrom, faces_.size(), generation);
}

void Graph::setFaceGeneration(FaceId f, long long generation) { setGenerations(faceGen_, f, f + std::size_t{1}, generation); }

std::size_t Graph::memoryBytes() const {
    std::size_t bytes = nodes_.capacity() * sizeof(NodeRec) + edges_.capacity() * sizeof(EdgeRec) +
                        dirty_.capacity() * sizeof(NodeId) + (z_.capacity() + radius_.capacity()) * sizeof(double) +
                        (nodeGen_.capacity() + edgeGen_.capacity() + faceGen_.capacity()) * sizeof(long long);
    for (const auto& k : kindNodes_) bytes += k.capacity() * sizeof(NodeId);
    for (const auto& p : pool_) bytes += p.capacity() * sizeof(Value);
    bytes += (nodeStyleList_.capacity() + edgeStyleList_.capacity() + faceStyleList_.capacity()) * sizeof(std::uint32_t) +
             styles_.memoryBytes();
    bytes += faces_.capacity() * sizeof(FaceRec) + corners_.capacity() * sizeof(CornerRec) +
             nodeCorners_.capacity() * sizeof(NodeCorners) + dirtyFaces_.capacity() * sizeof(FaceId);
    return bytes;
}

std::uint32_t& Graph::styleHead(GrowArray<std::uint32_t>& lists, std::uint32_t id, std::size_t capacity) {
    if (id >= lists.size()) lists.resize(std::max<std::size_t>(capacity, id + 1) + capacity / 2, StyleStore::kNone);
    return lists[id];
}

void Graph::setEdgeBend(EdgeId e, std::vector<vec2> points) {
    if (!edgeAlive(e)) throw std::logic_error("a bend for a dead edge");
    if (points.empty() && e >= edgeBends_.size()) return;
    if (e >= edgeBends_.size()) edgeBends_.resize(edges_.size());
    edgeBends_[e] = std::move(points);
}

}  // namespace g2d::rt
