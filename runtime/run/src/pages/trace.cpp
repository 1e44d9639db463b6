#include "g2d/trace.hpp"

#include <algorithm>
#include <map>

#include "g2d/face_triangles.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/svg_writer.hpp"
#include "g2d/value.hpp"

namespace g2d::rt {

namespace {

std::string num(double x) { return formatNumber(x); }

template <class T, class F>
std::string array(const std::vector<T>& items, F&& each) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? "," : "") + each(items[i]);
    return out + "]";
}

std::string ids(const std::vector<std::uint32_t>& v) {
    return array(v, [](std::uint32_t x) { return std::to_string(x); });
}
// [id, kind, x, y], and z for a 3D grammar.
std::string nodes(const std::vector<TraceNode>& v, bool space3d) {
    return array(v, [space3d](const TraceNode& n) {
        return "[" + std::to_string(n.id) + "," + std::to_string(n.kind) + "," + num(n.pos.x) + "," + num(n.pos.y) +
               (space3d ? "," + num(n.pos.z) : std::string()) + "]";
    });
}
std::string edges(const std::vector<TraceEdge>& v) {
    return array(v, [](const TraceEdge& e) {
        return "[" + std::to_string(e.id) + "," + std::to_string(e.kind) + "," + std::to_string(e.src) + "," +
               std::to_string(e.dst) + "]";
    });
}

// [id, kind, [corners]], and [triangles] for a 3D grammar.
std::string faces(const std::vector<TraceFace>& v, bool space3d) {
    return array(v, [space3d](const TraceFace& f) {
        return "[" + std::to_string(f.id) + "," + std::to_string(f.kind) + "," + ids(f.corners) +
               (space3d ? "," + ids(f.triangles) : std::string()) + "]";
    });
}

// How a kind is drawn in the player: the resolved style of one of its
// elements (tag, stroke, stroke width, fill, radius).
std::string kindStyle(const DrawItem& it) {
    const bool edge = it.cls == ElemClass::Edge, face = it.cls == ElemClass::Face;
    return "{\"tag\":" + jsonString(styleText(it, "tag", edge ? "line" : face ? "polygon" : "circle")) +
           ",\"stroke\":" + jsonString(styleText(it, "stroke", face ? "none" : "black")) +
           ",\"stroke_width\":" + num(styleNumber(it, "stroke_width", edge ? 0.05 : face ? 0 : 0.02)) +
           ",\"fill\":" + jsonString(styleText(it, "fill", "none")) + ",\"r\":" + num(styleNumber(it, "r", 0.1)) + "}";
}

std::vector<std::uint32_t> faceCorners(const Graph& g, FaceId f) {
    std::vector<std::uint32_t> corners;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) corners.push_back(g.cornerNode(c));
    return corners;
}

}  // namespace

TraceFace TraceRecorder::traceFace(const Graph& g, FaceId f) const {
    TraceFace out{f, g.faceKind(f), faceCorners(g, f), {}};
    if (!space3d_) return out;
    // The player draws a 3D face with the triangles the --view page uses.
    const FaceTriangles t = triangulateFace(g, f);
    if (t.problem != FaceShapeProblem::None) return out;
    for (const auto& tri : t.triangles)
        for (std::uint32_t p : tri) {
            if (t.points[p].node == kNoId) return TraceFace{f, out.kind, out.corners, {}};   // a bend: no node to name
            out.triangles.push_back(t.points[p].node);
        }
    return out;
}

void TraceRecorder::started() {
    space3d_ = grammar_.jsonSchema().space3d;
    const Graph& g = grammar_.graph();
    for (NodeId n = 0; n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n)) axiomNodes_.push_back(TraceNode{n, g.nodeKind(n), g.pos3(n)});
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) axiomEdges_.push_back(TraceEdge{e, g.edgeKind(e), g.source(e), g.target(e)});
    for (FaceId f = 0; f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) axiomFaces_.push_back(traceFace(g, f));
    for (const auto& k : g.kinds()) hasFaces_ = hasFaces_ || k.cls == ElemClass::Face;
    axiomDrawing_ = grammar_.drawItems();
    nodeCapacity_ = g.nodeCapacity();
    edgeCapacity_ = g.edgeCapacity();
    faceCapacity_ = g.faceCapacity();
}

void TraceRecorder::applying(std::size_t rule, std::size_t daughter, Match m, const Graph& g) {
    const RuleInfo& info = grammar_.rules().info(rule);
    Pending p;
    p.rule = info.name;
    p.daughter = static_cast<std::uint32_t>(daughter);
    p.nodes.assign(m.nodes, m.nodes + info.nodeKinds.size());
    p.edges.assign(m.edges, m.edges + info.edgeCount);
    p.faces.assign(m.faces, m.faces + info.faceCount);
    for (FaceId f : p.faces) facesBefore_.emplace_back(f, faceCorners(g, f));
    // What the rewrite may delete, move or rewire, as it is now.
    for (NodeId n : p.nodes) {
        for (CornerId c = g.firstCornerAt(n); c != kNoId; c = g.nextCornerAt(c))
            facesBefore_.emplace_back(g.cornerFace(c), faceCorners(g, g.cornerFace(c)));
        placesBefore_.emplace_back(n, g.pos3(n));
        for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e)) edgesBefore_.push_back(TraceEdge{e, g.edgeKind(e), g.source(e), g.target(e)});
        for (EdgeId e = g.firstIn(n); e != kNoId; e = g.nextIn(e)) edgesBefore_.push_back(TraceEdge{e, g.edgeKind(e), g.source(e), g.target(e)});
    }
    pending_.push_back(std::move(p));
}

void TraceRecorder::stepDone(long long step, const Graph& g) {
    TraceStep s;
    s.step = step;
    // The rule applied (every rewrite of a step is one rule's), not the one
    // whose code ran last: match repair runs other rules' searches.
    if (!pending_.empty()) s.rule = pending_.front().rule;
    for (const auto& p : pending_) {
        s.daughters.push_back(p.daughter);
        s.matchedNodes.insert(s.matchedNodes.end(), p.nodes.begin(), p.nodes.end());
        s.matchedEdges.insert(s.matchedEdges.end(), p.edges.begin(), p.edges.end());
        s.matchedFaces.insert(s.matchedFaces.end(), p.faces.begin(), p.faces.end());
    }
    auto unique = [](std::vector<std::uint32_t>& v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
    };
    unique(s.matchedNodes);
    unique(s.matchedEdges);
    unique(s.matchedFaces);
    // The first record of a face is from before the step's first rewrite.
    std::stable_sort(facesBefore_.begin(), facesBefore_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < facesBefore_.size(); ++i) {
        const auto& [f, corners] = facesBefore_[i];
        if (i > 0 && facesBefore_[i - 1].first == f) continue;
        if (!g.faceAlive(f)) {
            s.deletedFaces.push_back(f);
        } else if (TraceFace now = traceFace(g, f); now.corners != corners) {
            s.deletedFaces.push_back(f);
            s.addedFaces.push_back(std::move(now));
        }
    }
    for (FaceId f = static_cast<FaceId>(faceCapacity_); f < g.faceCapacity(); ++f)
        if (g.faceAlive(f)) s.addedFaces.push_back(traceFace(g, f));
    // Ids are never reused: what is new lies past the old capacities.
    for (NodeId n = static_cast<NodeId>(nodeCapacity_); n < g.nodeCapacity(); ++n)
        if (g.nodeAlive(n)) s.addedNodes.push_back(TraceNode{n, g.nodeKind(n), g.pos3(n)});
    for (EdgeId e = static_cast<EdgeId>(edgeCapacity_); e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) s.addedEdges.push_back(TraceEdge{e, g.edgeKind(e), g.source(e), g.target(e)});
    std::sort(placesBefore_.begin(), placesBefore_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < placesBefore_.size(); ++i) {
        const auto& [n, before] = placesBefore_[i];
        if (i > 0 && placesBefore_[i - 1].first == n) continue;
        if (!g.nodeAlive(n)) s.deletedNodes.push_back(n);
        else if (g.pos3(n) != before) s.moved.push_back(TraceNode{n, g.nodeKind(n), g.pos3(n)});
    }
    std::sort(edgesBefore_.begin(), edgesBefore_.end(), [](const TraceEdge& a, const TraceEdge& b) { return a.id < b.id; });
    for (std::size_t i = 0; i < edgesBefore_.size(); ++i) {
        const TraceEdge& e = edgesBefore_[i];
        if (i > 0 && edgesBefore_[i - 1].id == e.id) continue;
        if (!g.edgeAlive(e.id)) s.deletedEdges.push_back(e.id);
        else if (g.source(e.id) != e.src || g.target(e.id) != e.dst)
            s.rewired.push_back(TraceEdge{e.id, e.kind, g.source(e.id), g.target(e.id)});
    }
    steps_.push_back(std::move(s));
    pending_.clear();
    placesBefore_.clear();
    edgesBefore_.clear();
    facesBefore_.clear();
    nodeCapacity_ = g.nodeCapacity();
    edgeCapacity_ = g.edgeCapacity();
    faceCapacity_ = g.faceCapacity();
}

std::string TraceRecorder::json(const std::string& grammarName, std::uint64_t seed, const std::string& stopped) {
    const JsonSchema& schema = grammar_.jsonSchema();
    const std::vector<KindInfo>& kinds = grammar_.graph().kinds();
    // Each kind's look: from the final drawing, else the axiom's, else the defaults.
    std::map<int, std::string> styles;
    const Graph& g = grammar_.graph();
    auto note = [&](const std::vector<DrawItem>& items) {
        for (const auto& it : items) {
            const int kind = g.kindOf(it.cls, it.id);
            styles.emplace(kind, kindStyle(it));
        }
    };
    note(grammar_.drawItems());
    note(axiomDrawing_);
    std::string out = "{\"format\":\"g2d-trace-1\",\"grammar\":" + jsonString(grammarName) + ",\"seed\":" + std::to_string(seed) +
                      ",\"stopped\":" + jsonString(stopped) + (space3d_ ? ",\"space\":\"3d\"" : "") + ",\"kinds\":[";
    for (std::size_t k = 0; k < kinds.size(); ++k) {
        DrawItem fallback;
        fallback.cls = kinds[k].cls;
        const auto it = styles.find(static_cast<int>(k));
        out += std::string(k ? "," : "") + "{\"name\":" + jsonString(k < schema.kindNames.size() ? schema.kindNames[k] : "") +
               ",\"edge\":" + (kinds[k].cls == ElemClass::Edge ? "true" : "false") + ",\"directed\":" + (kinds[k].directed ? "true" : "false") +
               (kinds[k].cls == ElemClass::Face ? ",\"face\":true" : "") +
               ",\"style\":" + (it != styles.end() ? it->second : kindStyle(fallback)) + "}";
    }
    // Faces only for grammars that declare a face kind: the others' traces stay as they were.
    auto withFaces = [&](const std::string& text) { return hasFaces_ ? text : std::string(); };
    out += "],\"axiom\":{\"nodes\":" + nodes(axiomNodes_, space3d_) + ",\"edges\":" + edges(axiomEdges_) +
           withFaces(",\"faces\":" + faces(axiomFaces_, space3d_)) + "},\"steps\":[";
    for (std::size_t i = 0; i < steps_.size(); ++i) {
        const TraceStep& s = steps_[i];
        out += std::string(i ? ",\n" : "\n") + "{\"step\":" + std::to_string(s.step) + ",\"rule\":" + jsonString(s.rule) +
               ",\"daughters\":" + ids(s.daughters) + ",\"matched\":{\"nodes\":" + ids(s.matchedNodes) + ",\"edges\":" +
               ids(s.matchedEdges) + withFaces(",\"faces\":" + ids(s.matchedFaces)) + "},\"deleted\":{\"nodes\":" + ids(s.deletedNodes) +
               ",\"edges\":" + ids(s.deletedEdges) + withFaces(",\"faces\":" + ids(s.deletedFaces)) +
               "},\"added\":{\"nodes\":" + nodes(s.addedNodes, space3d_) + ",\"edges\":" + edges(s.addedEdges) +
               withFaces(",\"faces\":" + faces(s.addedFaces, space3d_)) + "},\"moved\":" + nodes(s.moved, space3d_) + ",\"rewired\":" + edges(s.rewired) + "}";
    }
    return out + "\n]}\n";
}

}  // namespace g2d::rt
