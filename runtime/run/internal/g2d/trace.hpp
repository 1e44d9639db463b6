#pragma once
// A derivation as data, step by step (g2d run --trace / --trace-json): the
// axiom, then per step the production and daughter, the matched elements,
// and what the step deleted, added, moved and rewired. Deltas only, so a
// million-step run stays a few bytes per step; the page thins its timeline
// instead (see trace_page.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "g2d/derivation.hpp"
#include "g2d/grammar_run.hpp"
#include "g2d/svg_writer.hpp"   // DrawItem

namespace g2d::rt {

struct TraceNode {
    std::uint32_t id;
    int kind;
    vec3 pos;   // z written for 3D grammars only
};
struct TraceEdge {
    std::uint32_t id;
    int kind;
    std::uint32_t src, dst;
};

struct TraceFace {
    std::uint32_t id;
    int kind;
    std::vector<std::uint32_t> corners;
    // 3D grammars: the face's triangles (triangulateFace) as node ids, three
    // a triangle; empty when the face cannot be triangulated as it is added.
    std::vector<std::uint32_t> triangles;
};

struct TraceStep {
    long long step = 0;
    std::string rule;
    std::vector<std::uint32_t> daughters;           // one per rewrite (several in a parallel step)
    std::vector<std::uint32_t> matchedNodes, matchedEdges;
    std::vector<std::uint32_t> deletedNodes, deletedEdges;
    std::vector<TraceNode> addedNodes, moved;       // moved: kept nodes at their new place
    std::vector<TraceEdge> addedEdges, rewired;     // rewired: kept edges with new ends
    std::vector<std::uint32_t> matchedFaces, deletedFaces;
    std::vector<TraceFace> addedFaces;
};

class TraceRecorder : public StepTracer {
public:
    explicit TraceRecorder(GrammarRun& grammar) : grammar_(grammar) {}

    // The axiom (call after GrammarRun::start).
    void started() override;
    void applying(std::size_t rule, std::size_t daughter, Match m, const Graph& g) override;
    void stepDone(long long step, const Graph& g) override;

    // The trace as JSON: kinds (with how each is drawn), the axiom, the steps
    // (format in docs/trace.md). `stopped` says why the derivation ended.
    std::string json(const std::string& grammarName, std::uint64_t seed, const std::string& stopped);

private:
    struct Pending {
        std::string rule;
        std::uint32_t daughter;
        std::vector<std::uint32_t> nodes, edges, faces;
    };
    GrammarRun& grammar_;
    std::vector<TraceNode> axiomNodes_;
    std::vector<TraceEdge> axiomEdges_;
    std::vector<TraceFace> axiomFaces_;
    std::vector<DrawItem> axiomDrawing_;
    std::vector<TraceStep> steps_;
    std::vector<Pending> pending_;
    // Before the step: the matched nodes' places and the edges at them (any may go).
    std::vector<std::pair<std::uint32_t, vec3>> placesBefore_;
    std::vector<TraceEdge> edgesBefore_;
    // And the faces at them, and the matched ones, with their corners: a face
    // that keeps its id but not its corners (a node inserted on its side) is
    // written as deleted and added again.
    std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> facesBefore_;
    std::size_t nodeCapacity_ = 0, edgeCapacity_ = 0, faceCapacity_ = 0;
    bool hasFaces_ = false;                    // the grammar declares a face kind (else no "faces" keys)
    bool space3d_ = false;                     // nodes keep their z, faces their triangles

    TraceFace traceFace(const Graph& g, FaceId f) const;
};

// The self-contained page: the trace, the final SVG, and a player. A 3D
// grammar's trace is played in the 3D viewer of the --view page instead
// (web/view/src/trace3d.js), without the SVG.
std::string writeTracePage(const std::string& traceJson, const std::string& finalSvg, const std::string& title,
                           bool space3d = false);

}  // namespace g2d::rt
