#pragma once
// The scheduler behind derive() (derivation.hpp, which specifies the order of
// its random draws): one object per derivation, with one method per way of
// stepping: a command list's command, a priority's generation, one rule's
// application (alone, in parallel, or proposed to the drawing step).
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "g2d/applied_hook.hpp"
#include "g2d/connected_guard.hpp"
#include "g2d/deadline.hpp"
#include "g2d/derivation.hpp"
#include "g2d/incremental_matches.hpp"
#include "g2d/node_merge.hpp"
#include "g2d/parallel_step.hpp"
#include "g2d/pick_lookahead.hpp"

namespace g2d::rt {

// Fills in the statistics however the derivation ends (returning or throwing).
class ResultSummary {
public:
    ResultSummary(DerivationResult& result, const PickLookahead& lookahead)
        : result_(result), lookahead_(lookahead), start_(std::chrono::steady_clock::now()) {}
    ~ResultSummary();
    ResultSummary(const ResultSummary&) = delete;
    ResultSummary& operator=(const ResultSummary&) = delete;
    void follow(const IncrementalMatches& sets) { sets_ = &sets; }

private:
    DerivationResult& result_;
    const PickLookahead& lookahead_;
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
    // After a rule's step: merging (if the rule merges), then the match sets
    // are brought up to date, reading the step's changes in place; they are
    // forgotten after it (before a full search, which reads none: a
    // generation's marks are still in the caches now). A generation passes
    // kAnyRule and its group's merge tolerance.
    void afterStep(std::size_t r, std::size_t daughter, long long step, NewIds from, double generationMerge = 0);
    void stepDone(long long step);
    NewIds newIds() const;

    Graph& g_;
    RuleSet& rules_;
    Rng& rng_;
    const DerivationOptions& limits_;
    DerivationResult& result_;
    const StepObserver& observer_;
    StepTracer* tracer_;
    std::vector<Group> groups_;
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

}  // namespace g2d::rt
