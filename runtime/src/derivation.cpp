#include "g2d/derivation.hpp"

#include "g2d/connected_guard.hpp"
#include "g2d/deadline.hpp"
#include "g2d/incremental_matches.hpp"
#include "g2d/intersection_guard.hpp"
#include "g2d/node_merge.hpp"
#include "g2d/parallel_step.hpp"
#include "g2d/compound_run.hpp"
#include "g2d/pick_lookahead.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <numeric>
#include <optional>

namespace g2d::rt {

std::size_t pickDaughter(const std::vector<double>& weights, Rng& rng) {
    if (weights.size() <= 1) return 0;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    const double u = rng.unit() * total;
    double cumulative = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        cumulative += weights[i];
        if (u < cumulative) return i;
    }
    // u rounded up to the total: the last daughter that can be chosen.
    std::size_t last = weights.size() - 1;
    while (last > 0 && !(weights[last] > 0)) --last;
    return last;
}

std::size_t chooseDaughter(RuleSet& rules, std::size_t rule, const RuleInfo& info, Match m, const Graph& g, Rng& rng,
                           std::vector<double>& scratch) {
    if (!info.matchWeighted) return pickDaughter(info.weights, rng);
    scratch = info.weights;
    rules.weigh(rule, m, g, scratch);
    return pickDaughter(scratch, rng);
}

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

struct Group {
    long long priority;
    std::vector<std::size_t> rules;
    std::optional<long long> limit;
    long long applied = 0;
    bool generation = false;        // `priority P generation;` (RuleInfo::generation)
    bool weighted = false;          // some rule's choiceWeight is not 1
    double mergeTolerance = 0;      // a generation's: the largest of its rules'
};

}  // namespace

namespace {

// Fills in the statistics however the derivation ends (returning or throwing).
class ResultSummary {
public:
    ResultSummary(DerivationResult& result, const PickLookahead& lookahead)
        : result_(result), lookahead_(lookahead), start_(std::chrono::steady_clock::now()) {}
    ~ResultSummary() {
        result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        result_.lookaheadGuesses = lookahead_.guesses();
        result_.lookaheadHits = lookahead_.hits();
        if (sets_) {
            result_.setRepairs = static_cast<long long>(sets_->setsRepaired());
            result_.setRepairsSkipped = static_cast<long long>(sets_->setsSkipped());
        }
    }
    void follow(const IncrementalMatches& sets) { sets_ = &sets; }

private:
    DerivationResult& result_;
    const PickLookahead& lookahead_;
    const IncrementalMatches* sets_ = nullptr;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

void derive(Graph& g, RuleSet& rules, Rng& rng, const DerivationOptions& limits, DerivationResult& result,
            const StepObserver& observer, StepTracer* tracer) {
    result = DerivationResult{};
    std::map<long long, Group> byPriority;
    bool neighbours = false;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) neighbours = neighbours || rules.info(r).readsNeighbours;
    g.trackNeighbours(neighbours);
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        const long long p = rules.info(r).priority;
        auto& grp = byPriority[p];
        grp.priority = p;
        grp.rules.push_back(r);
        grp.generation = grp.generation || rules.info(r).generation;
        grp.weighted = grp.weighted || rules.info(r).choiceWeight != 1;
        grp.mergeTolerance = std::max(grp.mergeTolerance, rules.info(r).mergeTolerance);
    }
    std::vector<Group> groups;
    for (auto& [p, grp] : byPriority) {
        if (auto it = limits.perPriority.find(p); it != limits.perPriority.end()) grp.limit = it->second;
        groups.push_back(std::move(grp));
    }

    std::vector<std::size_t> order;
    std::vector<double> weights;   // a match-weighted rule's, per application
    std::vector<const MatchSet*> generationSets;
    ParallelStep parallel;
    const AngleLayoutSpec* angles = rules.angleLayout();
    std::optional<AngleLayoutSpec> grammarCanvas;   // the spec in the grammar's `canvas`
    if (angles && limits.drawingCanvas) {
        grammarCanvas = *angles;
        grammarCanvas->settings.canvasLo = {limits.drawingCanvas->x0, limits.drawingCanvas->y0};
        grammarCanvas->settings.canvasHi = {limits.drawingCanvas->x1, limits.drawingCanvas->y1};
        angles = &*grammarCanvas;
    }
    if (angles) checkCanvasFits(*angles);
    AngleStep drawing(limits.wholeDrawings);
    ConnectedGuard connectedGuard;
    // Metropolis acceptance (drawing_cost.hpp): the counts and cost of the graph as it is.
    const bool costed = angles && rules.hasDrawingCost();
    const double temperature = costed ? rules.drawingTemperature() : 1;
    KindCounts counts = costed ? KindCounts::of(g, angles->kinds.size()) : KindCounts();
    KindCounts proposedCounts;
    double cost = costed ? rules.drawingCost(counts) : 0;
    PickLookahead lookahead;
    std::optional<IncrementalMatches> found;   // before the summary, which reads it as it goes
    ResultSummary summary(result, lookahead);
    std::optional<DeadlineWatch> deadline;
    if (limits.timeoutSeconds) deadline.emplace(*limits.timeoutSeconds);
    try {
        found.emplace(rules, g);
    } catch (const DeadlinePassed&) {
        throw timeLimit(limits, 0);
    }
    IncrementalMatches& sets = *found;
    summary.follow(sets);
    // A priority whose limit is used up never applies again: its rules' sets
    // are no longer kept (mutex STS: the requests, once every process made one).
    auto retireIfSpent = [&](const Group& grp) {
        if (grp.limit && grp.applied >= *grp.limit)
            for (std::size_t r : grp.rules) sets.retire(r);
    };
    for (const auto& grp : groups) retireIfSpent(grp);
    g.forgetChanges();
    // Merging keeps a spatial index of the nodes from the start when some rule merges.
    std::optional<NodeMerger> merger;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r)
        if (const double tolerance = rules.info(r).mergeTolerance; tolerance > 0 && !merger)
            merger.emplace(g, 4 * tolerance, [&](Graph& graph, FaceId from, FaceId to) { rules.copyFaceAttributes(graph, from, to); });
    // After a rule's step: merging (if the rule merges), then the match sets
    // are brought up to date, reading the step's changes in place; they are
    // forgotten after it (before a full search, which reads none: a
    // generation's marks are still in the caches now).
    // A generation passes kAnyRule and its group's merge tolerance.
    auto afterStep = [&](std::size_t r, std::size_t daughter, long long step, EdgeId newEdgesFrom, NodeId newNodesFrom,
                         double generationMerge = 0) {
        if (merger) {
            merger->sync(g);
            const double tolerance = r == IncrementalMatches::kAnyRule ? generationMerge : rules.info(r).mergeTolerance;
            if (tolerance > 0) merger->mergeChanged(g, tolerance);
        }
        sets.syncNear(g);
        const bool everything = IncrementalMatches::searchesEverything(g);
        if (everything) g.forgetChanges();
        try {
            sets.update(g, newEdgesFrom, newNodesFrom, everything, r, daughter);
            if (!everything) g.forgetChanges();
            if (limits.verifyMatches) sets.verify(g, step);   // a full search: conditions run again
        } catch (const DeadlinePassed&) {
            // While finding matches after the step: the step itself is complete.
            result.steps = step;
            if (tracer) tracer->stepDone(step, g);
            if (observer) observer(step, g);
            throw timeLimit(limits, step);
        }
    };
    auto stepDone = [&](long long step) {
        result.steps = step;
        if (tracer) tracer->stepDone(step, g);
        if (observer) observer(step, g);
        if (deadlineHasPassed()) throw timeLimit(limits, step);
        if (g.nodeCount() + g.edgeCount() > limits.maxElements)
            throw RunawayError("element_limit", "the graph grew past " + std::to_string(limits.maxElements) + " elements at step " +
                               std::to_string(step) + " (a runaway derivation? set a `limit`, or raise --max-elements)");
    };
    if (!rules.sequence().empty()) {
        // A command list: step k applies command k to all its matches (none:
        // the graph stays as it is); a compound runs its commands in turn.
        auto mayStep = [&] {
            if (!limits.steps || result.steps < *limits.steps) return true;
            result.stopped = StopReason::StepLimit;
            return false;
        };
        auto apply = [&](std::size_t r, const MatchSet& set, long long step, const ElementScope* const* scopes) -> std::size_t {
            if (!rules.info(r).intersect) {
                try {
                    return parallel.run(r, set, rules, g, rng, step, tracer, scopes);
                } catch (const DeadlinePassed&) {
                    throw timeLimit(limits, step);
                }
            }
            // Each application's additions are tested as it is committed (before a compound records them).
            IntersectionGuard guard;
            guard.begin(g);
            auto from = IntersectionGuard::capacities(g);
            const std::function<void()> previous = rules.onApplied;
            rules.onApplied = [&] {
                const auto to = IntersectionGuard::capacities(g);
                guard.admit(g, from, to);
                from = to;
                if (previous) previous();
            };
            std::size_t applied = 0;
            try {
                applied = parallel.run(r, set, rules, g, rng, step, tracer, scopes);
            } catch (const DeadlinePassed&) {
                rules.onApplied = previous;
                throw timeLimit(limits, step);
            } catch (...) {
                rules.onApplied = previous;
                throw;
            }
            rules.onApplied = previous;
            return applied - guard.cancelled();
        };
        auto afterCommand = [&](std::size_t r, long long step, EdgeId newEdgesFrom, NodeId newNodesFrom) {
            afterStep(r, IncrementalMatches::kAnyDaughter, step, newEdgesFrom, newNodesFrom);
        };
        CompoundRun compounds(g, rules, rng, parallel,
                              CompoundRun::Hooks{mayStep, [&] { return result.steps + 1; }, apply, afterCommand, stepDone});
        for (const SequenceEntry& entry : rules.sequence()) {
            if (entry.compound) {
                if (!compounds.run(entry.index, sets.of(rules.compounds()[entry.index].matchRule), result.applications)) return;
                continue;
            }
            if (!mayStep()) return;
            const long long step = result.steps + 1;
            const auto newEdgesFrom = static_cast<EdgeId>(g.edgeCapacity());
            const auto newNodesFrom = static_cast<NodeId>(g.nodeCapacity());
            const MatchSet& set = sets.of(entry.index);
            if (!set.empty()) {
                result.applications += static_cast<long long>(apply(entry.index, set, step, nullptr));
                afterCommand(entry.index, step, newEdgesFrom, newNodesFrom);
            }
            stepDone(step);
        }
        result.stopped = StopReason::Terminal;
        return;
    }
    while (true) {
        if (limits.steps && result.steps >= *limits.steps) {
            result.stopped = StopReason::StepLimit;
            break;
        }
        const long long step = result.steps + 1;
        const auto newEdgesFrom = static_cast<EdgeId>(g.edgeCapacity());   // ids are never reused
        const auto newNodesFrom = static_cast<NodeId>(g.nodeCapacity());
        bool applied = false;
        for (auto& grp : groups) {
            if (grp.limit && grp.applied >= *grp.limit) continue;
            if (grp.generation) {
                // Every rule of the priority at once (ParallelStep::runGeneration).
                generationSets.clear();
                bool any = false;
                for (std::size_t r : grp.rules) {
                    generationSets.push_back(&sets.of(r));
                    any = any || !sets.of(r).empty();
                }
                if (!any) continue;
                try {
                    result.applications +=
                        static_cast<long long>(parallel.runGeneration(grp.rules, generationSets, rules, g, rng, step, tracer));
                } catch (const DeadlinePassed&) {
                    throw timeLimit(limits, step);
                }
                ++grp.applied;
                retireIfSpent(grp);
                afterStep(IncrementalMatches::kAnyRule, IncrementalMatches::kAnyDaughter, step, newEdgesFrom, newNodesFrom,
                          grp.mergeTolerance);
                applied = true;
                break;
            }
            // Rules of one priority are tried in random order (a group of
            // one needs no copy: shuffling it draws nothing).
            const std::vector<std::size_t>* tryOrder = &grp.rules;
            if (grp.weighted) {
                // By weight among the rules that match (nothing drawn when none does).
                order.clear();
                if (const auto r = chooseWeightedRule(grp.rules, rules, sets, rng)) order.push_back(*r);
                tryOrder = &order;
            } else if (grp.rules.size() > 1) {
                order = grp.rules;
                shuffle(order, rng);
                tryOrder = &order;
            }
            for (std::size_t r : *tryOrder) {
                MatchSet& set = sets.of(r);
                if (set.empty()) continue;
                const RuleInfo& info = rules.info(r);
                std::size_t daughter = IncrementalMatches::kAnyDaughter;
                try {
                    if (info.parallel) {
                        result.applications += static_cast<long long>(parallel.run(r, set, rules, g, rng, step, tracer));
                    } else {
                        const Match m = picksOldest(info.pick) ? set.pickOldest(rng) : set.pickRandom(rng);
                        if (!lookahead.guessed(m)) sets.prefetch(g, m, set.nodes(), set.edges());
                        const std::size_t d = chooseDaughter(rules, r, info, m, g, rng, weights);
                        daughter = d;
                        lookahead.ahead(r, info, set, m, rng, sets, rules, g);
                        if (!angles) {
                            if (tracer) tracer->applying(r, d, m, g);
                            rules.prepareApplication(r, d, m, g, rng, step);
                            rules.commit(g, step);
                        } else {
                            rules.prepareApplication(r, d, m, g, rng, step);
                            // A refused proposal changes nothing, and the step
                            // counts (Algorithm 3's N) but not as an application
                            // of its priority.
                            double proposedCost = 0;
                            if (costed) {
                                proposedCounts = counts;
                                countChange(g, info.shapes[d], m, proposedCounts);
                                proposedCost = rules.drawingCost(proposedCounts);
                                if (!metropolisAccepts(proposedCost - cost, temperature, rng)) {
                                    rules.discardApplications();
                                    ++result.rejectedByCost;
                                    applied = true;
                                    break;
                                }
                            }
                            if (angles->connected && !connectedGuard.keepsConnected(g, info.shapes[d], m)) {
                                rules.discardApplications();
                                ++result.rejectedSplits;
                                applied = true;
                                break;
                            }
                            if (!drawing.propose(g, info.shapes[d], m, *angles, rng)) {
                                rules.discardApplications();
                                ++result.rejectedDrawings;
                                applied = true;
                                break;
                            }
                            if (tracer) tracer->applying(r, d, m, g);
                            rules.commit(g, step);
                            drawing.place(g, newNodesFrom);
                            if (costed) {
                                std::swap(counts, proposedCounts);
                                cost = proposedCost;
                            }
                        }
                        ++result.applications;
                    }
                } catch (const DeadlinePassed&) {
                    // Inside the step (a grammar function ran long): the graph is
                    // still the one of the last completed step.
                    throw timeLimit(limits, step);
                }
                ++grp.applied;
                retireIfSpent(grp);   // before the repair: a spent rule needs none
                afterStep(r, daughter, step, newEdgesFrom, newNodesFrom);
                applied = true;
                break;
            }
            if (applied) break;
        }
        if (!applied) {
            result.stopped = StopReason::Terminal;
            break;
        }
        stepDone(step);
    }
}

}  // namespace g2d::rt
