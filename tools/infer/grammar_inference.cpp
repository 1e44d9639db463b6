#include "infer/grammar_inference.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <unordered_map>

#include "infer/matching_groups.hpp"
#include "infer/rule_application.hpp"

namespace g2d::infer {
namespace {

// Algorithm 1's state. Graphs are grown simplest first: fewer open
// half-edges, then fewer glues, then earlier found.
class Inference {
public:
    Inference(const LabelledExample& ex, const InferOptions& options) : ex_(ex), options_(options) {}
    InferredGrammar run();

private:
    using QueueKey = std::tuple<std::size_t, int, int>;
    const LabelledExample& ex_;
    const InferOptions& options_;
    InferredGrammar out_;
    std::unordered_map<std::string, int> byCode_;
    std::set<QueueKey> queue_;
    std::vector<int> active_;      // graphs that are Active and not edge graphs, in order
    std::vector<int> checkedRules_;   // per graph: rules it was tested against
    std::vector<int> candidates_;     // edge graphs and graphs once active, in Algorithm 2's order

    HierarchyEntry& at(int g) { return out_.hierarchy[static_cast<std::size_t>(g)]; }
    QueueKey key(int g) { return {at(g).graph.boundary.size(), at(g).generation, at(g).order}; }
    bool simpler(int a, int b) { return key(a) < key(b); }

    int insert(HierarchyGraph graph);
    bool reducedByRules(int g);
    bool reduceByGroups(int g);
    void retryWith(int fresh);
    void addCandidate(int g);
    void startExample();
    void addStarter(HierarchyGraph g, const std::string& code);
    void grow(int g);
    int addRule(int left, std::vector<RulePiece> right);
};

// §5.6/§5.7: a graph whose boundary path turns more than 360° (either way)
// between two consecutive half-edges is not grown ("ignore graphs that have
// turned more than 360°"): closing it needs a path turning back as far.
bool turnsTooFar(const LabelledExample& ex, const HierarchyGraph& g) {
    const auto& B = g.boundary;
    for (std::size_t i = 0; i < B.size(); ++i) {
        const std::size_t j = (i + 1) % B.size();
        const int wrap = j == 0 ? 1 : 0;
        const double turned = ex.direction(B[j].half) - ex.direction(B[i].half) + 360.0 * (B[j].wind + wrap - B[i].wind);
        // The walk turns `turned` − 180° from coming back along B[i] to leaving along B[j].
        if (std::fabs(turned - 180.0) > 360.0 + 1e-9) return true;
    }
    return false;
}

// Each connected component of the example as a hierarchy graph.
std::vector<HierarchyGraph> exampleComponents(const LabelledExample& ex) {
    HierarchyGraph whole;
    for (int type : ex.vertexType) {
        whole.type.push_back(type);
        whole.links.emplace_back(ex.primitives[static_cast<std::size_t>(type)].halves.size());
    }
    auto slotOf = [&](int vertex, int half) {
        const auto& halves = ex.primitives[static_cast<std::size_t>(ex.vertexType[static_cast<std::size_t>(vertex)])].halves;
        return static_cast<int>(std::find(halves.begin(), halves.end(), half) - halves.begin());
    };
    for (std::size_t e = 0; e < ex.shape.edges.size(); ++e) {
        const ExampleEdge& edge = ex.shape.edges[e];
        const bool flipped = ex.edgeFlipped[e] != 0;   // `from` holds a unless flipped
        const int a = slotOf(edge.from, halfLabel(ex.edgeLabel[e], flipped)), b = slotOf(edge.to, halfLabel(ex.edgeLabel[e], !flipped));
        whole.links[static_cast<std::size_t>(edge.from)][static_cast<std::size_t>(a)] = {edge.to, b};
        whole.links[static_cast<std::size_t>(edge.to)][static_cast<std::size_t>(b)] = {edge.from, a};
    }
    return components(ex, whole);
}

int Inference::addRule(int left, std::vector<RulePiece> right) {
    InferredRule rule;
    rule.left = left;
    for (const RulePiece& p : right)
        if (!at(p.graph).graph.isEdgeGraph() && occursIn(at(left).graph, at(p.graph).graph)) rule.restructures = true;
    rule.right = std::move(right);
    out_.rules.push_back(std::move(rule));
    const int r = static_cast<int>(out_.rules.size()) - 1;
    at(left).state = GraphState::Reduced;
    at(left).reducedBy = r;
    return r;
}

// A rule simplifies g if its left side occurs in g, unless the rule
// restructures (§5.4) and g also contains one of its right graphs: g then
// descends from that graph, which the hierarchy grows on its own.
bool Inference::reducedByRules(int g) {
    const HierarchyGraph& graph = at(g).graph;
    int& from = checkedRules_[static_cast<std::size_t>(g)];
    for (; from < static_cast<int>(out_.rules.size()); ++from) {
        const InferredRule& rule = out_.rules[static_cast<std::size_t>(from)];
        if (rule.left == g || !occursIn(at(rule.left).graph, graph)) continue;
        bool insidePiece = false;
        if (rule.restructures)
            for (const RulePiece& p : rule.right)
                insidePiece = insidePiece || (!at(p.graph).graph.isEdgeGraph() && occursIn(at(p.graph).graph, graph));
        if (insidePiece) continue;
        at(g).state = GraphState::Reduced;
        at(g).reducedBy = from;
        return true;
    }
    return false;
}

// Algorithm 2 against every simpler graph still in the hierarchy: the
// edge graphs, the primitives and the active graphs, the largest first (so
// a rule has as few pieces as it can), then the simplest.
bool Inference::reduceByGroups(int g) {
    std::vector<int> index;
    std::vector<const HierarchyEntry*> candidates;
    for (int c : candidates_) {
        const HierarchyEntry& R = at(c);
        if (c == g || R.state != GraphState::Active || !simpler(c, g)) continue;
        index.push_back(c);
        candidates.push_back(&R);
    }
    std::vector<GroupEntry> S;
    const auto& B = at(g).graph.boundary;
    for (std::size_t i = 0; i < B.size(); ++i) S.push_back({B[i].half, B[i].wind, static_cast<int>(i)});
    std::vector<RulePiece> pieces;
    if (!findMatchingGroups(S, candidates, index, pieces)) return false;
    addRule(g, std::move(pieces));
    return true;
}

// Candidates for Algorithm 2 stay sorted: the largest boundary first, then the simplest.
void Inference::addCandidate(int g) {
    const auto before = [&](int a, int b) {
        return at(a).halves.size() != at(b).halves.size() ? at(a).halves.size() > at(b).halves.size() : key(a) < key(b);
    };
    candidates_.insert(std::upper_bound(candidates_.begin(), candidates_.end(), g, before), g);
}

int Inference::insert(HierarchyGraph graph) {
    std::string code = canonicalCode(graph);
    if (const auto it = byCode_.find(code); it != byCode_.end()) return it->second;
    const int g = static_cast<int>(out_.hierarchy.size());
    HierarchyEntry entry;
    entry.graph = std::move(graph);
    entry.order = g;
    entry.generation = entry.graph.generation();
    for (const BoundaryEntry& e : entry.graph.boundary) {
        entry.halves.push_back(e.half);
        entry.halfMask |= std::uint64_t{1} << (e.half % 64);
    }
    std::sort(entry.halves.begin(), entry.halves.end());
    out_.hierarchy.push_back(std::move(entry));
    checkedRules_.push_back(0);
    byCode_.emplace(std::move(code), g);
    if (at(g).graph.isEdgeGraph()) {
        addCandidate(g);
        return g;
    }
    if (reducedByRules(g)) return g;
    if (at(g).graph.complete()) {   // §5.3.1: a starter rule, ∅ <-> the graph
        addRule(g, {});
        return g;
    }
    if (reduceByGroups(g)) return g;
    if (turnsTooFar(ex_, at(g).graph)) {
        at(g).state = GraphState::Pruned;
        return g;
    }
    active_.push_back(g);
    addCandidate(g);
    queue_.insert(key(g));
    retryWith(g);
    return g;
}

// §5.1: "we check if G can be simplified or if G can be used to simplify
// another graph" — every active graph with more half-edges, and at least
// the new graph's half-edges, is matched again.
void Inference::retryWith(int fresh) {
    const HierarchyEntry& f = at(fresh);
    const std::vector<int> snapshot = active_;
    for (int x : snapshot) {
        const HierarchyEntry& X = at(x);
        if (x == fresh || X.state != GraphState::Active || X.halves.size() < f.halves.size() || !simpler(fresh, x)) continue;
        if ((f.halfMask & ~X.halfMask) != 0 || !std::includes(X.halves.begin(), X.halves.end(), f.halves.begin(), f.halves.end()))
            continue;
        if (reduceByGroups(x)) queue_.erase(key(x));
    }
    std::erase_if(active_, [&](int a) { return at(a).state != GraphState::Active; });
}

void Inference::grow(int g) {
    // Copy: inserting children grows the hierarchy under the reference.
    const HierarchyGraph graph = at(g).graph;
    const int m = static_cast<int>(graph.boundary.size());
    for (int i = 0; i < m; ++i) {
        const int want = complement(graph.boundary[static_cast<std::size_t>(i)].half);
        for (std::size_t p = 0; p < ex_.primitives.size(); ++p) {
            const auto& halves = ex_.primitives[p].halves;
            for (std::size_t s = 0; s < halves.size(); ++s)
                if (halves[s] == want) insert(branchGlue(ex_, graph, i, static_cast<int>(p), static_cast<int>(s)));
        }
    }
    for (int i = 0; i < m && !options_.noLoops; ++i) {
        HierarchyGraph child;
        if (loopGlue(ex_, graph, i, child)) insert(std::move(child));
    }
}

InferredGrammar Inference::run() {
    for (std::size_t l = 0; l < ex_.labels.size(); ++l) insert(edgeGraph(ex_, static_cast<int>(l)));
    out_.edgeGraphs = static_cast<int>(out_.hierarchy.size());
    for (std::size_t p = 0; p < ex_.primitives.size(); ++p) out_.primitiveGraph.push_back(insert(primitiveGraph(ex_, static_cast<int>(p))));
    while (!queue_.empty()) {
        const int g = std::get<2>(*queue_.begin());
        queue_.erase(queue_.begin());
        if (at(g).state != GraphState::Active) continue;
        if (reducedByRules(g)) continue;
        if (at(g).generation > options_.maxGeneration ||
            static_cast<int>(at(g).graph.boundary.size()) > options_.maxHalfEdges ||
            static_cast<int>(out_.hierarchy.size()) >= options_.maxGraphs) {
            at(g).state = GraphState::LeftOver;
            continue;
        }
        grow(g);
    }
    std::erase_if(active_, [&](int a) { return at(a).state != GraphState::Active; });
    startExample();
    return std::move(out_);
}

// The example's own components are complete graphs; the limits may stop the
// growth before it reaches them, and two restructuring rules (§5.4) can each
// leave to the other a complete graph that neither reduces. So the example
// is followed down: each complete graph is simplified by the first rule that
// applies and leads nowhere it has been; one that no rule takes further gets
// a starter rule. Then the grammar reduces the example to nothing, and makes it.
void Inference::startExample() {
    std::vector<HierarchyGraph> todo = exampleComponents(ex_);
    std::size_t limit = 0;
    for (const HierarchyGraph& c : todo) limit += c.type.size();
    limit *= 4;   // restructuring may grow a graph; not past this
    std::set<std::string> seen;
    for (std::size_t visits = 0; !todo.empty() && visits < 100000; ++visits) {
        HierarchyGraph g = std::move(todo.back());
        todo.pop_back();
        const std::string code = canonicalCode(g);
        if (!seen.insert(code).second) continue;
        bool simplified = false;
        for (std::size_t r = 0; r < out_.rules.size() && !simplified && g.type.size() <= limit; ++r) {
            const InferredRule& rule = out_.rules[r];
            if (rule.starter()) continue;
            const std::vector<int> image = findOccurrence(at(rule.left).graph, g);
            if (image.empty()) continue;
            std::vector<HierarchyGraph> parts = applyDestructively(ex_, out_, rule, g, image);
            const bool fresh = std::none_of(parts.begin(), parts.end(), [&](const HierarchyGraph& p) { return seen.count(canonicalCode(p)) > 0; });
            if (!fresh) continue;
            for (HierarchyGraph& p : parts) todo.push_back(std::move(p));
            simplified = true;
        }
        if (!simplified) addStarter(std::move(g), code);
    }
}

void Inference::addStarter(HierarchyGraph g, const std::string& code) {
    int index;
    if (const auto it = byCode_.find(code); it != byCode_.end()) {
        index = it->second;
    } else {
        index = static_cast<int>(out_.hierarchy.size());
        HierarchyEntry entry;
        entry.graph = std::move(g);
        entry.order = index;
        entry.generation = entry.graph.generation();
        out_.hierarchy.push_back(std::move(entry));
        checkedRules_.push_back(0);
        byCode_.emplace(code, index);
    }
    for (const InferredRule& r : out_.rules)
        if (r.starter() && r.left == index) return;
    const GraphState state = at(index).state;
    const int reducedBy = at(index).reducedBy;
    addRule(index, {});
    if (state == GraphState::Reduced) at(index).reducedBy = reducedBy;   // a rule reduces it too: keep that one
}

}  // namespace

int InferredGrammar::leftOver() const {
    int n = 0;
    for (const HierarchyEntry& h : hierarchy) n += h.state == GraphState::LeftOver ? 1 : 0;
    return n;
}
int InferredGrammar::starters() const {
    int n = 0;
    for (const InferredRule& r : rules) n += r.starter() ? 1 : 0;
    return n;
}

InferredGrammar inferGrammar(const LabelledExample& ex, const InferOptions& options) {
    return Inference(ex, options).run();
}

}  // namespace g2d::infer
