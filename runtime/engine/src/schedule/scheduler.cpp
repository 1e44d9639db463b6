// The scheduler behind derive() (derivation.hpp specifies the order of its
// random draws): one object per derivation, with one method per way of
// stepping: a command list's command, a priority's generation, one rule's
// application (alone, in parallel, or proposed to the drawing step). It is
// local to this file, so that the compiler inlines the methods called once
// per step into the step loop.
#include "g2d/derivation.hpp"

#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "g2d/applied_hook.hpp"
#include "g2d/connected_guard.hpp"
#include "g2d/deadline.hpp"
#include "g2d/incremental_matches.hpp"
#include "g2d/node_merge.hpp"
#include "g2d/parallel_step.hpp"
#include "g2d/pick_lookahead.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "g2d/compound_run.hpp"
#include "g2d/intersection_guard.hpp"

namespace g2d::rt {

namespace {

// A rule of `group` with a match, with probability ∝ its choiceWeight; one draw.
std::optional<std::size_t> chooseWeightedRule(const std::vector<std::size_t>& group, RuleSet& rules, IncrementalMatches& sets,
                                              Rng& rng) {
    double total = 0;
    for (std::size_t r : group)
        if (!sets.of(r).empty()) total += rules.info(r).choiceWeight;
    if (!(total > 0)) return std::nullopt;
    const double u = rng.unit() * total;
    double cumulative = 0;
    std::optional<std::size_t> last;
    for (std::size_t r : group) {
        if (sets.of(r).empty()) continue;
        cumulative += rules.info(r).choiceWeight;
        last = r;
        if (u < cumulative) return r;
    }
    return last;   // u rounded up to the total
}

// A canvas no edge fits in draws nothing: an error, not a run of refusals.
void checkCanvasFits(const AngleLayoutSpec& spec) {
    const vec2 size = spec.settings.canvasHi - spec.settings.canvasLo;
    const EdgeGeometry* least = nullptr;
    for (const EdgeGeometry& k : spec.kinds) {
        if (!k.given) continue;
        if (k.minLength * std::abs(std::cos(k.angle)) <= size.x && k.minLength * std::abs(std::sin(k.angle)) <= size.y) return;
        if (!least || k.minLength < least->minLength) least = &k;
    }
    if (!least) return;   // no edge kinds: nodes alone fit anywhere
    char text[160];
    std::snprintf(text, sizeof text, "the canvas, %g x %g, is smaller than the shortest edge of every edge kind (the least is %g long)",
                  size.x, size.y, least->minLength);
    throw std::invalid_argument(std::string(text) + ": nothing can be drawn in it");
}

RunawayError timeLimit(const DerivationOptions& limits, long long step) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g s", limits.timeoutSeconds.value_or(0));
    return RunawayError("time_limit", std::string("the derivation ran past the time limit of ") + seconds + " at step " +
                                          std::to_string(step) + " (raise --timeout)");
}

// Fills in the statistics however the derivation ends (returning or throwing).
class ResultSummary {
public:
    ResultSummary(DerivationResult& result, const PickLookahead& lookahead, const Graph& g)
        : result_(result), lookahead_(lookahead), g_(g), start_(std::chrono::steady_clock::now()) {}
    ~ResultSummary();
    ResultSummary(const ResultSummary&) = delete;
    ResultSummary& operator=(const ResultSummary&) = delete;
    void follow(const IncrementalMatches& sets) { sets_ = &sets; }

private:
    DerivationResult& result_;
    const PickLookahead& lookahead_;
    const Graph& g_;
    const IncrementalMatches* sets_ = nullptr;
    std::chrono::steady_clock::time_point start_;
};

class Scheduler {
public:
    // Finds every rule's matches on `g` (throws RunawayError past the time limit).
    Scheduler(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& limits, DerivationResult& result,
              const StepObserver& observer, StepTracer* tracer);

    // Steps until no rule applies or a limit stops the derivation.
    void run();

private:
    // The rules of one priority, in the order the scheduler tries them.
    struct Group {
        long long priority;
        std::vector<std::size_t> rules;
        std::optional<long long> limit;
        long long applied = 0;
        bool generation = false;        // `priority P generation;` (RuleInfo::generation)
        bool weighted = false;          // some rule's choiceWeight is not 1
        double mergeTolerance = 0;      // a generation's: the largest of its rules'
    };
    // Where the ids a step creates start (ids are never reused).
    struct NewIds {
        EdgeId edges;
        NodeId nodes;
    };

    std::vector<Group> groupsByPriority();
    // A command list: step k applies command k to all its matches (none: the
    // graph stays as it is); a compound runs its commands in turn.
    void runSequence();
    bool mayStep();
    // One command on all its matches (within `scopes` in a compound): how many were applied.
    std::size_t applyCommand(std::size_t r, const MatchSet& set, long long step, const ElementScope* const* scopes);
    // The priorities from the lowest value up, each step applying the first that can.
    void runPriorities();
    // Whether the priority's turn applied something (a refused drawing counts).
    bool stepGroup(Group& grp, long long step, NewIds from);
    bool stepGeneration(Group& grp, long long step, NewIds from);
    // One application of rule r, or with `parallel` all it can take; the daughter applied, if one.
    std::size_t applyRule(std::size_t r, MatchSet& set, long long step, NewIds from, bool& refused);
    // With `layout angles`: the application is proposed to the drawing step; false when refused.
    bool proposeDrawn(std::size_t r, std::size_t d, Match m, long long step, NewIds from);
    // A priority whose limit is used up never applies again: its rules' sets
    // are no longer kept (mutex STS: the requests, once every process made one).
    void retireIfSpent(const Group& grp);
    // A step applied rule r: with its own limit used up, it retires too.
    void spendRule(std::size_t r) {
        if (ruleLeft_[r] > 0 && --ruleLeft_[r] == 0) found_->retire(r);
    }
    // After a rule's step: merging (if the rule merges), then the match sets
    // are brought up to date, reading the step's changes in place; they are
    // forgotten after it (before a full search, which reads none: a
    // generation's marks are still in the caches now). A generation passes
    // kAnyRule and its group's merge tolerance.
    [[gnu::always_inline]] inline void afterStep(std::size_t r, std::size_t daughter, long long step, NewIds from, double generationMerge = 0);
    [[gnu::always_inline]] inline void stepDone(long long step);
    NewIds newIds() const;

    Graph& g_;
    RuleSet& rules_;
    Rng& rng_;
    const DerivationOptions& limits_;
    DerivationResult& result_;
    const StepObserver& observer_;
    StepTracer* tracer_;
    std::vector<Group> groups_;
    std::vector<long long> ruleLeft_;   // per rule: the steps its `limit` still allows (-1: no limit)
    std::vector<std::size_t> order_;
    std::vector<double> weights_;   // a match-weighted rule's, per application
    std::vector<const MatchSet*> generationSets_;
    ParallelStep parallel_;
    const AngleLayoutSpec* angles_ = nullptr;
    std::optional<AngleLayoutSpec> grammarCanvas_;   // the spec in the grammar's `canvas`
    AngleStep drawing_;
    ConnectedGuard connectedGuard_;
    // Metropolis acceptance (drawing_cost.hpp): the counts and cost of the graph as it is.
    bool costed_ = false;
    double temperature_ = 1;
    KindCounts counts_, proposedCounts_;
    double cost_ = 0;
    PickLookahead lookahead_;
    std::optional<IncrementalMatches> found_;   // before the summary, which reads it as it goes
    ResultSummary summary_;
    std::optional<DeadlineWatch> deadline_;
    // Merging keeps a spatial index of the nodes from the start when some rule merges.
    std::optional<NodeMerger> merger_;
};

ResultSummary::~ResultSummary() {
    result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    result_.lookaheadGuesses = lookahead_.guesses();
    result_.lookaheadHits = lookahead_.hits();
    result_.facesAgainstNeighbours = g_.faceCounts().againstNeighbour;
    result_.insertsWithoutSide = g_.faceCounts().insertsWithoutSide;
    if (sets_) {
        result_.setRepairs = static_cast<long long>(sets_->setsRepaired());
        result_.setRepairsSkipped = static_cast<long long>(sets_->setsSkipped());
    }
}

Scheduler::Scheduler(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& limits, DerivationResult& result,
                     const StepObserver& observer, StepTracer* tracer)
    : g_(g), rules_(rules), rng_(rng), limits_(limits), result_(result), observer_(observer), tracer_(tracer),
      drawing_(limits.wholeDrawings), summary_(result, lookahead_, g) {
    result_ = DerivationResult{};
    groups_ = groupsByPriority();
    angles_ = rules_.angleLayout();
    if (angles_ && limits_.drawingCanvas) {
        grammarCanvas_ = *angles_;
        grammarCanvas_->settings.canvasLo = {limits_.drawingCanvas->x0, limits_.drawingCanvas->y0};
        grammarCanvas_->settings.canvasHi = {limits_.drawingCanvas->x1, limits_.drawingCanvas->y1};
        angles_ = &*grammarCanvas_;
    }
    if (angles_) checkCanvasFits(*angles_);
    costed_ = angles_ && rules_.hasDrawingCost();
    temperature_ = costed_ ? rules_.drawingTemperature() : 1;
    if (costed_) counts_ = KindCounts::of(g_, angles_->kinds.size());
    cost_ = costed_ ? rules_.drawingCost(counts_) : 0;
    if (limits_.timeoutSeconds) deadline_.emplace(*limits_.timeoutSeconds);
    try {
        found_.emplace(rules_, g_);
    } catch (const DeadlinePassed&) {
        throw timeLimit(limits_, 0);
    }
    summary_.follow(*found_);
    for (const auto& grp : groups_) retireIfSpent(grp);
    ruleLeft_.assign(rules_.ruleCount(), -1);
    for (const auto& [r, limit] : limits_.perRule) {
        ruleLeft_[r] = std::max(limit, 0LL);
        if (limit <= 0) found_->retire(r);
    }
    g_.forgetChanges();
    for (std::size_t r = 0; r < rules_.ruleCount(); ++r)
        if (const double tolerance = rules_.info(r).mergeTolerance; tolerance > 0 && !merger_)
            merger_.emplace(g_, 4 * tolerance, [this](Graph& graph, FaceId from, FaceId to) { rules_.copyFaceAttributes(graph, from, to); });
}

std::vector<Scheduler::Group> Scheduler::groupsByPriority() {
    std::map<long long, Group> byPriority;
    bool neighbours = false;
    for (std::size_t r = 0; r < rules_.ruleCount(); ++r) neighbours = neighbours || rules_.info(r).readsNeighbours;
    g_.trackNeighbours(neighbours);
    for (std::size_t r = 0; r < rules_.ruleCount(); ++r) {
        const RuleInfo& info = rules_.info(r);
        auto& grp = byPriority[info.priority];
        grp.priority = info.priority;
        grp.rules.push_back(r);
        grp.generation = grp.generation || info.generation;
        grp.weighted = grp.weighted || info.choiceWeight != 1;
        grp.mergeTolerance = std::max(grp.mergeTolerance, info.mergeTolerance);
    }
    std::vector<Group> groups;
    for (auto& [p, grp] : byPriority) {
        if (auto it = limits_.perPriority.find(p); it != limits_.perPriority.end()) grp.limit = it->second;
        groups.push_back(std::move(grp));
    }
    return groups;
}

void Scheduler::run() {
    if (!rules_.sequence().empty()) runSequence();
    else runPriorities();
}

Scheduler::NewIds Scheduler::newIds() const {
    return NewIds{static_cast<EdgeId>(g_.edgeCapacity()), static_cast<NodeId>(g_.nodeCapacity())};
}

void Scheduler::retireIfSpent(const Group& grp) {
    if (grp.limit && grp.applied >= *grp.limit)
        for (std::size_t r : grp.rules) found_->retire(r);
}

inline void Scheduler::afterStep(std::size_t r, std::size_t daughter, long long step, NewIds from, double generationMerge) {
    IncrementalMatches& sets = *found_;
    if (merger_) {
        merger_->sync(g_);
        const double tolerance = r == IncrementalMatches::kAnyRule ? generationMerge : rules_.info(r).mergeTolerance;
        if (tolerance > 0) merger_->mergeChanged(g_, tolerance);
    }
    sets.syncNear(g_);
    const bool everything = IncrementalMatches::searchesEverything(g_);
    if (everything) g_.forgetChanges();
    try {
        sets.update(g_, from.edges, from.nodes, everything, r, daughter);
        if (!everything) g_.forgetChanges();
        if (limits_.verifyMatches) sets.verify(g_, step);   // a full search: conditions run again
    } catch (const DeadlinePassed&) {
        // While finding matches after the step: the step itself is complete.
        result_.steps = step;
        if (tracer_) tracer_->stepDone(step, g_);
        if (observer_) observer_(step, g_);
        throw timeLimit(limits_, step);
    }
}

inline void Scheduler::stepDone(long long step) {
    result_.steps = step;
    if (tracer_) tracer_->stepDone(step, g_);
    if (observer_) observer_(step, g_);
    if (deadlineHasPassed()) throw timeLimit(limits_, step);
    if (g_.nodeCount() + g_.edgeCount() > limits_.maxElements)
        throw RunawayError("element_limit", "the graph grew past " + std::to_string(limits_.maxElements) + " elements at step " +
                           std::to_string(step) + " (a runaway derivation? set a `limit`, or raise --max-elements)");
}

// ---- command lists -------------------------------------------------------------

bool Scheduler::mayStep() {
    if (!limits_.steps || result_.steps < *limits_.steps) return true;
    result_.stopped = StopReason::StepLimit;
    return false;
}

std::size_t Scheduler::applyCommand(std::size_t r, const MatchSet& set, long long step, const ElementScope* const* scopes) {
    try {
        if (!rules_.info(r).intersect) return parallel_.run(r, set, rules_, g_, rng_, step, tracer_, scopes);
        // Each application runs under a journal and is tested as it is
        // committed (before a compound records what it made).
        IntersectionGuard guard(rules_.info(r).intersectInPlane);
        guard.begin(g_);
        GraphJournal journal;
        struct Detach {   // however the step ends, the graph keeps no journal
            Graph& g;
            ~Detach() { g.endJournal(false); }
        } detach{g_};
        g_.beginJournal(journal);
        const std::function<void()> previous = rules_.appliedHook();
        AppliedHook hook(rules_, [&] {
            guard.admit(g_);
            g_.beginJournal(journal);
            if (previous) previous();
        });
        const std::size_t applied = parallel_.run(r, set, rules_, g_, rng_, step, tracer_, scopes);
        result_.rejectedIntersections += static_cast<long long>(guard.cancelled());
        return applied - guard.cancelled();
    } catch (const DeadlinePassed&) {
        throw timeLimit(limits_, step);
    }
}

void Scheduler::runSequence() {
    auto afterCommand = [&](std::size_t r, long long step, EdgeId newEdgesFrom, NodeId newNodesFrom) {
        afterStep(r, IncrementalMatches::kAnyDaughter, step, NewIds{newEdgesFrom, newNodesFrom});
    };
    CompoundRun compounds(g_, rules_, rng_, parallel_,
                          CompoundRun::Hooks{[this] { return mayStep(); }, [this] { return result_.steps + 1; },
                                             [this](std::size_t r, const MatchSet& set, long long step, const ElementScope* const* scopes) {
                                                 return applyCommand(r, set, step, scopes);
                                             },
                                             afterCommand, [this](long long step) { stepDone(step); },
                                             [this] { ++result_.compoundsWithoutInstances; }},
                          limits_.repeatCounts);
    const bool finished = forEachCommand(rules_.sequence(), limits_.repeatCounts, [&](const SequenceEntry& entry) {
        if (entry.kind == SequenceEntry::Compound)
            return compounds.run(entry.index, found_->of(rules_.compounds()[entry.index].matchRule), result_.applications);
        if (!mayStep()) return false;
        const long long step = result_.steps + 1;
        const NewIds from = newIds();
        const MatchSet& set = found_->of(entry.index);
        if (!set.empty()) {
            result_.applications += static_cast<long long>(applyCommand(entry.index, set, step, nullptr));
            afterCommand(entry.index, step, from.edges, from.nodes);
        }
        stepDone(step);
        return true;
    });
    if (finished) result_.stopped = StopReason::Terminal;
}

// ---- priorities ----------------------------------------------------------------

void Scheduler::runPriorities() {
    while (true) {
        if (limits_.steps && result_.steps >= *limits_.steps) {
            result_.stopped = StopReason::StepLimit;
            break;
        }
        const long long step = result_.steps + 1;
        const NewIds from = newIds();
        bool applied = false;
        for (auto& grp : groups_) {
            if (grp.limit && grp.applied >= *grp.limit) continue;
            applied = grp.generation ? stepGeneration(grp, step, from) : stepGroup(grp, step, from);
            if (applied) break;
        }
        if (!applied) {
            result_.stopped = StopReason::Terminal;
            break;
        }
        stepDone(step);
    }
}

bool Scheduler::stepGeneration(Group& grp, long long step, NewIds from) {
    // Every rule of the priority at once (ParallelStep::runGeneration).
    generationSets_.clear();
    bool any = false;
    for (std::size_t r : grp.rules) {
        generationSets_.push_back(&found_->of(r));
        any = any || !found_->of(r).empty();
    }
    if (!any) return false;
    try {
        result_.applications += static_cast<long long>(parallel_.runGeneration(grp.rules, generationSets_, rules_, g_, rng_, step, tracer_));
    } catch (const DeadlinePassed&) {
        throw timeLimit(limits_, step);
    }
    ++grp.applied;
    retireIfSpent(grp);
    afterStep(IncrementalMatches::kAnyRule, IncrementalMatches::kAnyDaughter, step, from, grp.mergeTolerance);
    return true;
}

bool Scheduler::stepGroup(Group& grp, long long step, NewIds from) {
    // Rules of one priority are tried in random order (a group of one needs
    // no copy: shuffling it draws nothing).
    const std::vector<std::size_t>* tryOrder = &grp.rules;
    if (grp.weighted) {
        // By weight among the rules that match (nothing drawn when none does).
        order_.clear();
        if (const auto r = chooseWeightedRule(grp.rules, rules_, *found_, rng_)) order_.push_back(*r);
        tryOrder = &order_;
    } else if (grp.rules.size() > 1) {
        order_ = grp.rules;
        shuffle(order_, rng_);
        tryOrder = &order_;
    }
    for (std::size_t r : *tryOrder) {
        MatchSet& set = found_->of(r);
        if (set.empty()) continue;
        bool refused = false;
        std::size_t daughter = IncrementalMatches::kAnyDaughter;
        try {
            daughter = applyRule(r, set, step, from, refused);
        } catch (const DeadlinePassed&) {
            // Inside the step (a grammar function ran long): the graph is
            // still the one of the last completed step.
            throw timeLimit(limits_, step);
        }
        // A refused proposal changes nothing, and the step counts
        // (Algorithm 3's N) but not as an application of its priority.
        if (refused) return true;
        ++grp.applied;
        retireIfSpent(grp);   // before the repair: a spent rule needs none
        spendRule(r);
        afterStep(r, daughter, step, from);
        return true;
    }
    return false;
}

std::size_t Scheduler::applyRule(std::size_t r, MatchSet& set, long long step, NewIds from, bool& refused) {
    const RuleInfo& info = rules_.info(r);
    if (info.parallel) {
        result_.applications += static_cast<long long>(parallel_.run(r, set, rules_, g_, rng_, step, tracer_));
        return IncrementalMatches::kAnyDaughter;
    }
    IncrementalMatches& sets = *found_;
    const Match m = picksOldest(info.pick) ? set.pickOldest(rng_) : set.pickRandom(rng_);
    if (!lookahead_.guessed(m)) sets.prefetch(g_, m, set.nodes(), set.edges());
    const std::size_t d = chooseDaughter(rules_, r, info, m, g_, rng_, weights_);
    lookahead_.ahead(r, info, set, m, rng_, sets, rules_, g_);
    if (!angles_) {
        if (tracer_) tracer_->applying(r, d, m, g_);
        rules_.prepareApplication(r, d, m, g_, rng_, step);
        rules_.commit(g_, step);
    } else if (!proposeDrawn(r, d, m, step, from)) {
        refused = true;
        return d;
    }
    ++result_.applications;
    return d;
}

bool Scheduler::proposeDrawn(std::size_t r, std::size_t d, Match m, long long step, NewIds from) {
    const RuleInfo& info = rules_.info(r);
    rules_.prepareApplication(r, d, m, g_, rng_, step);
    double proposedCost = 0;
    if (costed_) {
        proposedCounts_ = counts_;
        countChange(g_, info.shapes[d], m, proposedCounts_);
        proposedCost = rules_.drawingCost(proposedCounts_);
        if (!metropolisAccepts(proposedCost - cost_, temperature_, rng_)) {
            rules_.discardApplications();
            ++result_.rejectedByCost;
            return false;
        }
    }
    if (angles_->connected && !connectedGuard_.keepsConnected(g_, info.shapes[d], m)) {
        rules_.discardApplications();
        ++result_.rejectedSplits;
        return false;
    }
    if (!drawing_.propose(g_, info.shapes[d], m, *angles_, rng_)) {
        rules_.discardApplications();
        ++result_.rejectedDrawings;
        return false;
    }
    if (tracer_) tracer_->applying(r, d, m, g_);
    rules_.commit(g_, step);
    drawing_.place(g_, from.nodes);
    if (costed_) {
        std::swap(counts_, proposedCounts_);
        cost_ = proposedCost;
    }
    return true;
}

}  // namespace

void derive(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& limits, DerivationResult& result,
            const StepObserver& observer, StepTracer* tracer) {
    Scheduler(g, rules, rng, limits, result, observer, tracer).run();
}

}  // namespace g2d::rt
