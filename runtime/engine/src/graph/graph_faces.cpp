// The graph's faces (graph.hpp): corner records threaded through two
// intrusive doubly linked lists, the face's cycle and the node's corners.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "g2d/geometry3.hpp"
#include "g2d/graph.hpp"
#include "g2d/ops.hpp"

namespace g2d::rt {

Graph::NodeCorners& Graph::cornersAt(NodeId n) {
    if (n >= nodeCorners_.size()) nodeCorners_.resize(std::max<std::size_t>(nodes_.size(), n + 1) + nodes_.size() / 2);
    return nodeCorners_[n];
}

FaceId Graph::addFace(int kind, std::span<const NodeId> corners, long long age) {
    if (corners.size() < 3) throw OpError("a face needs at least 3 corners, got " + std::to_string(corners.size()));
    for (std::size_t i = 0; i < corners.size(); ++i) {
        if (!nodeAlive(corners[i])) throw OpError("a corner of a face is not a live node");
        for (std::size_t j = 0; j < i; ++j)
            if (corners[i] == corners[j]) throw OpError("a face's corners must be distinct nodes");
    }
    const auto id = static_cast<FaceId>(faces_.size());
    auto& ofKind = kindNodes_[kind];
    FaceRec rec;
    rec.age = age;
    rec.kind = static_cast<std::int16_t>(kind);
    rec.slot = pooled(kind) ? newAttrBlock(kind, nullptr) : kNoId;
    rec.slotInKind = static_cast<std::uint32_t>(ofKind.size());
    rec.firstCorner = static_cast<CornerId>(corners_.size());
    rec.cornerCount = static_cast<std::uint32_t>(corners.size());
    faces_.push_back(rec);
    ofKind.push_back(id);
    const CornerId first = rec.firstCorner;
    const auto k = static_cast<CornerId>(corners.size());
    for (CornerId i = 0; i < k; ++i) {
        NodeCorners& at = cornersAt(corners[i]);
        const CornerId c = first + i;
        corners_.push_back(CornerRec{corners[i], id, first + (i + 1) % k, first + (i + k - 1) % k, at.first, kNoId});
        if (at.first != kNoId) corners_[at.first].prevAtNode = c;
        at.first = c;
        ++at.count;
        // A node's faces are a fact of the node (n.faces, e.faces at its edges):
        // its matches are found again.
        touchNode(corners[i]);
    }
    dirtyFaces_.push_back(id);
    faces_[id].marks |= kFaceChanged;
    ++liveFaces_;
    if (trackNeighbours_) touchNeighbourAnchors(id);
    return id;
}

void Graph::removeFace(FaceId f) {
    FaceRec& rec = faces_[f];
    if (!rec.alive) return;
    if (trackNeighbours_) touchNeighbourAnchors(f);
    CornerId c = rec.firstCorner;
    for (std::uint32_t i = 0; i < rec.cornerCount; ++i, c = corners_[c].next) unlinkAtNode(c);
    const bool journaled = journal_ && f < journal_->from[2];
    if (journaled) {
        // Out of its kind's index and dead, but its attributes and styles
        // stay until the journal is kept (reviveFace brings it back).
        journal_->entries.push_back({GraphJournal::Op::FaceRemoved, f, capacities()});
        unindex(rec, faces_);
    } else {
        retire(rec, faces_, faceStyleList_, f);
    }
    if (f < faceHoles_.size()) faceHoles_[f].clear();
    touchFace(f);
    --liveFaces_;
}

void Graph::setFaceHoles(FaceId f, std::vector<std::vector<NodeId>> rings) {
    if (!faceAlive(f)) throw std::logic_error("holes for a dead face");
    if (rings.empty() && f >= faceHoles_.size()) return;
    if (f >= faceHoles_.size()) faceHoles_.resize(faces_.size());
    faceHoles_[f] = std::move(rings);
}

// A face's corners changed: its own facts, its anchor's matches, and (for
// `neighbours`) the faces around it.
void Graph::faceReshaped(FaceId f) {
    touchFace(f);
    touchNode(anchorOf(f));
    if (trackNeighbours_) touchNeighbourAnchors(f);
}

CornerId Graph::insertCornerAfter(CornerId c, NodeId m) {
    const auto id = static_cast<CornerId>(corners_.size());
    if (journal_) journal_->entries.push_back({GraphJournal::Op::Corner, id, capacities()});
    const FaceId f = corners_[c].face;
    NodeCorners& at = cornersAt(m);
    const CornerId next = corners_[c].next;
    corners_.push_back(CornerRec{m, f, next, c, at.first, kNoId});
    corners_[c].next = id;
    corners_[next].prev = id;
    if (at.first != kNoId) corners_[at.first].prevAtNode = id;
    at.first = id;
    ++at.count;
    ++faces_[f].cornerCount;
    touchNode(m);
    return id;
}

void Graph::unlinkAtNode(CornerId c) {
    CornerRec& cr = corners_[c];
    NodeCorners& at = nodeCorners_[cr.node];
    if (cr.prevAtNode != kNoId) corners_[cr.prevAtNode].nextAtNode = cr.nextAtNode;
    else at.first = cr.nextAtNode;
    if (cr.nextAtNode != kNoId) corners_[cr.nextAtNode].prevAtNode = cr.prevAtNode;
    --at.count;
    touchNode(cr.node);
}

void Graph::removeCorner(CornerId c) {
    if (journal_) journal_->lost = true;
    CornerRec& cr = corners_[c];
    FaceRec& face = faces_[cr.face];
    if (trackNeighbours_) touchNeighbourAnchors(cr.face);   // those beside the old shape
    unlinkAtNode(c);
    corners_[cr.prev].next = cr.next;
    corners_[cr.next].prev = cr.prev;
    if (face.firstCorner == c) face.firstCorner = cr.next;
    --face.cornerCount;
    cr.next = cr.prev = kNoId;
}

void Graph::moveCorner(CornerId c, NodeId n) {
    if (journal_) journal_->lost = true;
    if (trackNeighbours_) touchNeighbourAnchors(corners_[c].face);
    unlinkAtNode(c);
    NodeCorners& at = cornersAt(n);
    CornerRec& cr = corners_[c];
    cr.node = n;
    cr.prevAtNode = kNoId;
    cr.nextAtNode = at.first;
    if (at.first != kNoId) corners_[at.first].prevAtNode = c;
    at.first = c;
    ++at.count;
    touchNode(n);
}

int Graph::insertBetween(NodeId a, NodeId b, NodeId m) {
    // The side's corners first: inserting changes the lists being walked.
    std::vector<CornerId> after;
    for (CornerId c = firstCornerAt(a); c != kNoId; c = nextCornerAt(c)) {
        const CornerId next = nextCorner(c), prev = prevCorner(c);
        if (cornerNode(next) == b) after.push_back(c);          // the face runs a -> b
        else if (cornerNode(prev) == b) after.push_back(prev);  // b -> a
    }
    int grown = 0;
    for (CornerId c : after) {
        const FaceId f = cornerFace(c);
        bool has = false;
        CornerId k = firstCorner(f);
        for (int i = 0; i < cornerCount(f) && !has; ++i, k = nextCorner(k)) has = cornerNode(k) == m;
        if (has) continue;
        insertCornerAfter(c, m);
        faceReshaped(f);
        ++grown;
    }
    return grown;
}

void Graph::removeFacesAt(NodeId n) {
    while (firstCornerAt(n) != kNoId) removeFace(cornerFace(firstCornerAt(n)));
    for (auto& rings : faceHoles_)   // empty but after a drawing's faces were added
        std::erase_if(rings, [n](const std::vector<NodeId>& ring) { return std::find(ring.begin(), ring.end(), n) != ring.end(); });
}

int Graph::sideFaceCount(NodeId u, NodeId v) const {
    int count = 0;
    eachSideUse(u, v, [&](FaceId, bool) { ++count; });
    return count;
}

void Graph::neighbours(FaceId f, std::vector<FaceId>& out) const {
    out.clear();
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c))
        eachSideUse(cornerNode(c), cornerNode(nextCorner(c)), [&](FaceId g, bool) {
            if (g != f && std::find(out.begin(), out.end(), g) == out.end()) out.push_back(g);
        });
}

int Graph::neighbourCount(FaceId f) const {
    std::vector<FaceId> out;
    neighbours(f, out);
    return static_cast<int>(out.size());
}

double Graph::signedArea(FaceId f) const {
    double twice = 0;
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c)) {
        const vec2 a = pos(cornerNode(c)), b = pos(cornerNode(nextCorner(c)));
        twice += a.x * b.y - b.x * a.y;
    }
    return twice / 2;
}

double Graph::area(FaceId f) const { return std::abs(signedArea(f)); }

// The sum of the sides' lengths and the mean of the corners, in 2D or 3D
// (`at` reads a node's position).
template <class At>
double Graph::sidesLength(FaceId f, At at) const {
    double sum = 0;
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c)) sum += length(at(cornerNode(nextCorner(c))) - at(cornerNode(c)));
    return sum;
}

template <class At>
auto Graph::cornerMean(FaceId f, At at) const {
    decltype(at(NodeId{})) sum{};
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c)) sum = sum + at(cornerNode(c));
    return sum / static_cast<double>(cornerCount(f));
}

double Graph::perimeter(FaceId f) const { return sidesLength(f, [this](NodeId n) { return pos(n); }); }
vec2 Graph::centroid(FaceId f) const { return cornerMean(f, [this](NodeId n) { return pos(n); }); }
double Graph::perimeter3(FaceId f) const { return sidesLength(f, [this](NodeId n) { return pos3(n); }); }
vec3 Graph::centroid3(FaceId f) const { return cornerMean(f, [this](NodeId n) { return pos3(n); }); }

double Graph::area3(FaceId f) const {
    std::vector<vec3> corners;
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c)) corners.push_back(pos3(cornerNode(c)));
    return polygonArea3(corners);
}


// Newell's sum, taken about the first corner so that far-off faces keep their precision.
vec3 Graph::vectorArea(FaceId f) const {
    vec3 twice{0, 0, 0};
    const vec3 origin = pos3(anchorOf(f));
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c))
        twice = twice + cross(pos3(cornerNode(c)) - origin, pos3(cornerNode(nextCorner(c))) - origin);
    return twice / 2.0;
}

Graph::Bounds3 Graph::bounds3(bool edge, std::uint32_t id) const {
    auto widen = [](Bounds3& b, vec3 p) {
        b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
        b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
    };
    if (edge) {
        Bounds3 b{pos3(source(id)), pos3(source(id))};
        widen(b, pos3(target(id)));
        return b;
    }
    CornerId c = firstCorner(id);
    Bounds3 b{pos3(cornerNode(c)), pos3(cornerNode(c))};
    for (int i = 0; i < cornerCount(id); ++i, c = nextCorner(c)) widen(b, pos3(cornerNode(c)));
    return b;
}

void Graph::copyFaceAttrs(FaceId from, FaceId to) {
    const int kind = faces_[from].kind;
    if (!pooled(kind)) return;
    for (std::size_t i = 0; i < defaults_[kind].size(); ++i) initFaceAttr(to, static_cast<int>(i), faceAttr(from, static_cast<int>(i)));
}

void Graph::setFaceAttr(FaceId f, int i, Value v) {
    initFaceAttr(f, i, std::move(v));
    touchFaceValues(f);
}

void Graph::touchFacesAt(NodeId n) {
    for (CornerId c = firstCornerAt(n); c != kNoId; c = nextCornerAt(c)) touchNode(anchorOf(cornerFace(c)));
}

// Every face sharing a corner with f (a superset of those sharing a side):
// both `neighbours` and `touching` read them.
void Graph::touchNeighbourAnchors(FaceId f) {
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c))
        for (CornerId k = firstCornerAt(cornerNode(c)); k != kNoId; k = nextCornerAt(k))
            if (cornerFace(k) != f) touchNode(anchorOf(cornerFace(k)));
}

int Graph::touchingCount(FaceId f) const {
    std::vector<FaceId> seen;
    CornerId c = firstCorner(f);
    for (int i = 0; i < cornerCount(f); ++i, c = nextCorner(c))
        for (CornerId k = firstCornerAt(cornerNode(c)); k != kNoId; k = nextCornerAt(k))
            if (cornerFace(k) != f && std::find(seen.begin(), seen.end(), cornerFace(k)) == seen.end()) seen.push_back(cornerFace(k));
    return static_cast<int>(seen.size());
}

void Graph::initFaceAttr(FaceId f, int i, Value v) { pool_[faces_[f].kind][attrIndex(faces_[f].kind, faces_[f].slot, i)] = std::move(v); }

StyleList Graph::faceStyle(FaceId f) const {
    return styles_.list((faces_[f].marks & kStyled) ? faceStyleList_[f] : StyleStore::kNone);
}

void Graph::setFaceStyle(FaceId f, StyleProp prop, Value&& v) {
    faces_[f].marks |= kStyled;
    styles_.set(styleHead(faceStyleList_, f, faces_.size()), prop, std::move(v));
}

void Graph::setFaceStyle(FaceId f, StyleProp prop, const Value& v) { setFaceStyle(f, prop, Value(v)); }

void Graph::touchFace(FaceId f) {
    if (!(faces_[f].marks & kFaceChanged)) dirtyFaces_.push_back(f);
    faces_[f].marks |= kFaceChanged;
}

}  // namespace g2d::rt
