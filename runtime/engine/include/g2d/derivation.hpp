#pragma once
// The scheduler of a derivation, exactly as the thesis (§4.1): each step goes
// through the priorities from the lowest value up, tries the rules of one
// priority in random order, applies the first rule that has a match, and
// starts again from the lowest priority. The rules themselves (matching and
// rewriting) are supplied by a back end through RuleSet: the interpreter
// walks the IR, generated code runs specialised loops. Both share this file,
// so they draw random numbers in the same order.
//
// The matches of every rule are found once on the axiom and then kept up to
// date (incremental_matches.hpp): after a step, the graph reports the nodes
// that changed; for each rule, every match binding a node within the rule's
// radius of a changed node is dropped and the matches binding such a node are
// found again, anchored there. So a step costs what changed, not the size of
// the graph.
//
// Random draws per step, in this order:
//   1. for each priority visited, a Fisher–Yates shuffle of its rules
//      (no draw for a single rule);
//   2. the match: below(n) over the rule's match set in its order (random), or
//      over the tied oldest matches (oldest); no draw when there is one;
//   3. the daughter: one unit() draw when the rule has several daughters;
//   4. whatever the daughter's expressions draw, in source order;
//   5. with `layout angles`, the drawing step's (angle_drawing.cpp), whether
//      it accepts the application or not.
// A parallel step shuffles the matches (random) or sorts them oldest first,
// then takes each match that does not overlap those already taken, drawing
// its daughter (3) in that order; then it evaluates the taken matches'
// expressions (4) and rewrites them in the order of the rule's match set
// (which matches are taken is the draw's; the set's order keeps the
// rewrite's memory accesses close together).
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "g2d/angle_step.hpp"
#include "g2d/command_list.hpp"
#include "g2d/derivation_result.hpp"
#include "g2d/drawing_cost.hpp"
#include "g2d/generations.hpp"
#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"
#include "g2d/near_queries.hpp"
#include "g2d/pick.hpp"
#include "g2d/rng.hpp"
#include "g2d/rule_info.hpp"
#include "g2d/view_box.hpp"

namespace g2d::rt {

// What repair needs of one pattern node, from RuleInfo (repairAnchors):
// the runtime's repair and generated repairs read the same.
struct RepairAnchor {
    int kind = -1;                      // -1: any
    std::uint8_t directions = 3;        // the host's edge lists it reads (RepairArea::kOut | kIn)
    bool readsAllEdges = true;          // every edge at its host, not only the pattern's
    bool newHostAddsNothing = false;    // RuleInfo::newHostAddsNothing
};
std::vector<RepairAnchor> repairAnchors(const RuleInfo& info);

// The nodes around a step's changes whose matches a rule finds again
// (IncrementalMatches): every node of `nodes` is marked in `seen` as
// mark * 8 + 1 (search it at every pattern node) or mark * 8 + 2 * d, where
// d says which of its edge lists alone changed (kOut: outgoing, kIn:
// incoming, or both): search it at the pattern nodes reading those.
struct RepairArea {
    static constexpr std::uint8_t kOut = 1, kIn = 2;   // edge lists
    std::span<const NodeId> nodes;
    const std::uint32_t* seen = nullptr;
    std::uint32_t mark = 0;
    EdgeId newEdgesFrom = 0;   // the edges the step added have ids from this one on (ids are never reused)
    NodeId newNodesFrom = kNoId;   // likewise the nodes it added
    bool contains(NodeId h) const { return (seen[h] >> 3) == mark; }
    // Whether host `h` is searched at a pattern node reading the edge lists
    // `reads` (0: none). A match binding a new edge is added from the first
    // of its pattern nodes whose host is searched (see bindsNewEdge).
    bool searched(std::uint8_t reads, NodeId h) const {
        const std::uint32_t s = seen[h];
        return (s >> 3) == mark && ((s & 1) != 0 || ((s >> 1) & reads) != 0);
    }
    // For a node of `nodes`: whether it is searched at every pattern node,
    // and which of its edge lists changed (when not).
    bool full(NodeId h) const { return (seen[h] & 1) != 0; }
    std::uint8_t edgeChanges(NodeId h) const { return static_cast<std::uint8_t>((seen[h] >> 1) & 3); }
    // Whether a match binds an edge the step added. Such a match is added
    // from the first of its pattern nodes whose host is searched; any other
    // match the set lacks (it binds a node that changed itself or lies in
    // the radius, or an area node at a pattern node reading every edge) from
    // the first of those (`stale`). A node whose edges alone changed,
    // searched at a pattern node reading only the pattern's edges, thus adds
    // only matches binding a new edge: the others were kept.
    bool bindsNewEdge(const EdgeId* e, int edges) const {
        for (int i = 0; i < edges; ++i)
            if (e[i] >= newEdgesFrom) return true;
        return false;
    }
    bool stale(NodeId h, bool readsAllEdges) const { return contains(h) && (full(h) || readsAllEdges); }

    // The decisions of repair, for both back ends. Whether area node `h`
    // (full: full(h); of kind hostKind) is searched at pattern node `a`:
    // some list it reads changed (a node of the area changed itself or had
    // a list change, so one reading both lists always qualifies), the kind
    // fits, and a new host there can add something.
    // (Inlined into generated repairs, where the anchors are constants.)
    [[gnu::always_inline]] bool searchesAt(NodeId h, bool full, int hostKind, const RepairAnchor& a) const {
        return (full || a.directions == (kOut | kIn) || (a.directions & edgeChanges(h)) != 0) &&
               (a.kind < 0 || a.kind == hostKind) && !(a.newHostAddsNothing && h >= newNodesFrom);
    }
    // The search from there keeps only matches binding an edge from this id
    // on (kNoId: every match): where only the node's edges changed and the
    // pattern node reads only its own edges, the others were kept.
    [[gnu::always_inline]] EdgeId newEdgesOnly(bool full, const RepairAnchor& a) const { return !full && !a.readsAllEdges ? newEdgesFrom : kNoId; }
    // Whether a match found at pattern node `p` is added there: only from the
    // first of its anchors that adds it (see bindsNewEdge).
    [[gnu::always_inline]] bool firstAnchor(int p, const NodeId* n, const EdgeId* e, int edges, const RepairAnchor* anchors) const {
        const bool fresh = bindsNewEdge(e, edges);
        for (int q = 0; q < p; ++q)
            if (fresh ? searched(anchors[q].directions, n[q]) : stale(n[q], anchors[q].readsAllEdges)) return false;
        return true;
    }
};

// Elements a chosen daughter deletes or changes (for parallel steps).
struct WriteSet {
    std::vector<NodeId> nodes;
    std::vector<EdgeId> edges;
    std::vector<FaceId> faces;
    void clear() {
        nodes.clear();
        edges.clear();
        faces.clear();
    }
};

class RuleSet {
public:
    virtual ~RuleSet() = default;
    virtual std::size_t ruleCount() const = 0;
    virtual const RuleInfo& info(std::size_t rule) const = 0;
    // Every match of `rule` on `g`, in a deterministic order, appended to
    // `out` (reset by the caller to the rule's widths).
    virtual void findMatches(std::size_t rule, const Graph& g, MatchBuffer& out) = 0;
    // Every match of `rule` that binds pattern node `node` to host node `host`.
    // With `newEdgesFrom` (not kNoId), only those binding an edge whose id is
    // at least that (an edge the step added): a binding none of whose
    // pattern edges is new is dropped as soon as its last one is bound, so
    // conditions searched after that point are not evaluated for it (every
    // back end drops at the same point).
    virtual void findAnchored(std::size_t rule, const Graph& g, int node, NodeId host, MatchBuffer& out,
                              EdgeId newEdgesFrom = kNoId) = 0;
    // Adds to `set` every match of `rule` that binds a node of `area`, each
    // once (the caller has dropped those the set held), in the order of the
    // area's nodes, then pattern nodes, then
    // findAnchored's order (so every back end fills the set alike). This one
    // runs findAnchored per (node, pattern node) through `scratch`;
    // generated code replaces it with inlined searches.
    virtual void repair(std::size_t rule, const Graph& g, const RepairArea& area, const RepairAnchor* anchors, MatchSet& set,
                        MatchBuffer& scratch);
    // What applying `daughter` to `m` deletes or changes, appended to `out`.
    virtual void writeSet(std::size_t rule, std::size_t daughter, Match m, WriteSet& out) const = 0;
    // A matchWeighted rule's weights for match m: `weights` comes as
    // info.weights, and the daughters whose weight reads the match get theirs.
    // Throws (placed at the weight) when one is negative or not finite, or all are 0.
    virtual void weigh(std::size_t rule, Match m, const Graph& g, std::vector<double>& weights) {
        (void)rule, (void)m, (void)g, (void)weights;
    }
    // Evaluates everything the daughter computes, on the graph as it is now
    // (before the step), and keeps it (and the match's ids) until commit().
    // The scheduler calls prepareApplication, which notes the application's
    // generation first (when tracked).
    virtual void prepare(std::size_t rule, std::size_t daughter, Match m, const Graph& g, Rng& rng,
                         long long step) = 0;
    // Applies every prepared application, in order, and forgets them.
    virtual void commit(Graph& g, long long step) = 0;
    // Forgets the prepared applications without applying them (a drawing
    // the `layout angles` step rejected).
    virtual void discard() = 0;
    // `layout angles` (angle_step.hpp): each application is drawn before it
    // is committed. Null: positions come from the rules.
    virtual const AngleLayoutSpec* angleLayout() const { return nullptr; }
    // Its cost and temperature (`layout angles { cost = …; temperature = …; }`,
    // drawing_cost.hpp). The cost of `counts` throws (placed at the cost)
    // when it is not finite; the temperature (1 unless given) when it is not
    // positive and finite.
    virtual bool hasDrawingCost() const { return false; }
    virtual double drawingCost(const KindCounts& counts) {
        (void)counts;
        return 0;
    }
    virtual double drawingTemperature() { return 1; }
    // Asks for the cache lines a rewrite of `m` reads beyond the graph's
    // records (generated code: the matched elements' attribute records), for
    // a likely later pick (PickLookahead). Reads the elements' records, which
    // should be cached by then. Nothing by default.
    virtual void prefetchData(std::size_t rule, Match m, const Graph& g) const {
        (void)rule, (void)m, (void)g;
    }
    // Gives a face that merging split off (node_merge.hpp) the attributes of
    // the face it came from (the graph's own pools by default).
    virtual void copyFaceAttributes(Graph& g, FaceId from, FaceId to) { g.copyFaceAttrs(from, to); }
    // A face the run adds itself (drawn_faces.hpp), with its kind's default
    // attributes (the graph's own pools by default).
    virtual FaceId addFaceWithDefaults(Graph& g, int kind, std::span<const NodeId> corners, long long age) {
        return g.addFace(kind, corners, age);
    }
    // A G^3 command list (`sequence { … }`): these entries in this order,
    // a rule applied once to all its matches at once (a parallel step,
    // whatever the rule says), a compound as compound_run.hpp says; then the
    // derivation ends. Empty: the priorities decide.
    virtual const std::vector<SequenceEntry>& sequence() const {
        static const std::vector<SequenceEntry> none;
        return none;
    }
    // The compound commands the sequence names (directly or within each other).
    virtual const std::vector<CompoundInfo>& compounds() const {
        static const std::vector<CompoundInfo> none;
        return none;
    }
    // The values of compound `compound`'s lets for the instance at match `m`
    // (its match rule's), in order, on the graph as it is now.
    virtual std::vector<Value> compoundValues(std::size_t compound, Match m, const Graph& g, Rng& rng) {
        (void)compound, (void)m, (void)g, (void)rng;
        return {};
    }
    // The hook applicationDone calls after each application, when set:
    // compound scopes take in what each application created, the
    // intersection guard tests it. The scheduler sets one for a scope
    // (AppliedHook, applied_hook.hpp), which puts back the one it replaced.
    const std::function<void()>& appliedHook() const { return onApplied_; }
    void setAppliedHook(std::function<void()> hook) { onApplied_ = std::move(hook); }
    // The scheduler's way to prepare and drop applications, and the back
    // ends' to report each one committed: they keep the thesis tool's
    // `.generation` (generations.hpp) when the grammar reads it.
    void prepareApplication(std::size_t rule, std::size_t daughter, Match m, const Graph& g, Rng& rng, long long step) {
        if (tracksGenerations_) {
            const RuleInfo& i = info(rule);
            generations_.prepared(m, static_cast<int>(i.nodeKinds.size()), i.edgeCount, i.faceCount, g);
        }
        prepare(rule, daughter, m, g, rng, step);
    }
    void discardApplications() {
        generations_.clear();
        discard();
    }
    void applicationDone(Graph& g) {
        if (tracksGenerations_) generations_.applied(g);
        if (onApplied_) onApplied_();
    }
    // Whether the grammar reads `.generation`.
    bool tracksGenerations() const { return tracksGenerations_; }
    // The spatial index of negative conditions asking for a node near a
    // point (RuleInfo::nearKinds): the searches read it, IncrementalMatches
    // keeps it up to date while a derivation runs.
    NearQueries& nearQueries() { return near_; }

protected:
    // The back end says so (the interpreter when built, generated code in
    // start()) for a grammar that reads `.generation`.
    void setTracksGenerations(bool tracks) { tracksGenerations_ = tracks; }

private:
    NearQueries near_;
    GenerationStamps generations_;
    std::function<void()> onApplied_;
    bool tracksGenerations_ = false;
};

// A runaway guard: a derivation stops with an error past this many nodes +
// edges unless told otherwise (about 1 GB compiled).
inline constexpr std::size_t kDefaultMaxElements = 10'000'000;

struct DerivationOptions {
    std::optional<long long> steps;               // global limit (none: unlimited)
    std::map<long long, long long> perPriority;   // priority -> limit
    std::map<std::size_t, long long> perRule;     // rule -> limit (`rule R limit N`), in steps of the rule
    std::vector<long long> repeatCounts;          // per `repeat N { … }` of the command lists (SequenceEntry::index)
    std::size_t maxElements = kDefaultMaxElements;
    std::optional<double> timeoutSeconds;         // wall time of the derivation (none: unlimited)
    // After every step, check every rule's kept matches against a full search
    // (IncrementalMatches::verify; std::logic_error on a difference). Costs a
    // full search per step: for tests, and for users who suspect the engine.
    bool verifyMatches = false;
    // `layout angles` without a canvas of its own draws in the grammar's `canvas`.
    std::optional<ViewBox> drawingCanvas;
    // `layout angles`: build every proposal's system from the whole graph,
    // not from the part it can move (AngleStep; for tests: the two must agree).
    bool wholeDrawings = false;
};

// StopReason and DerivationResult: derivation_result.hpp.

// Called after every step (for progress displays).
using StepObserver = std::function<void(long long step, const Graph& g)>;

// Follows a derivation rewrite by rewrite (for --trace): told each match
// before it is rewritten, and when the step is complete.
class StepTracer {
public:
    virtual ~StepTracer() = default;
    // The axiom is built, before the first step (deriveGrammar calls it).
    virtual void started() {}
    virtual void applying(std::size_t rule, std::size_t daughter, Match m, const Graph& g) = 0;
    virtual void stepDone(long long step, const Graph& g) = 0;
};

// A resource bound was hit (elements, wall time, the default step limit):
// the graph is as the last completed step left it.
class RunawayError : public std::runtime_error {
public:
    // `bound`: "element_limit" or "time_limit" (as the JSON output's "stopped").
    RunawayError(std::string bound, const std::string& message) : std::runtime_error(message), bound_(std::move(bound)) {}
    const std::string& bound() const { return bound_; }

private:
    std::string bound_;
};

// Derives until no rule applies or a limit is reached. `result` is kept up
// to date: when a bound or a run-time error ends the derivation with an
// exception, it describes the steps completed until then (statistics included).
void derive(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& options, DerivationResult& result,
            const StepObserver& observer = {}, StepTracer* tracer = nullptr);

// Helpers shared with tests: the selection rules, as specified above.
std::size_t pickDaughter(const std::vector<double>& weights, Rng& rng);
// The daughter for an application of `rule` to m: by its weights, read from
// the match where they depend on it (`scratch` holds them).
std::size_t chooseDaughter(RuleSet& rules, std::size_t rule, const RuleInfo& info, Match m, const Graph& g, Rng& rng,
                           std::vector<double>& scratch);
template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

}  // namespace g2d::rt
