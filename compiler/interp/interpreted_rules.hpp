#pragma once
// The interpreter's rules: matching walks each rule's lowered match lists over
// the runtime's indexes; rewriting executes the daughter's lowered rewrite program.
#include <optional>
#include <vector>

#include "g2d/derivation.hpp"
#include "interp/program_state.hpp"
#include "interp/rewrite_executor.hpp"
#include "lower/lowered_program.hpp"

namespace g2d::interp {

class InterpretedRules : public rt::RuleSet {
public:
    // Throws EvalError if a parameter-dependent weight is not positive.
    explicit InterpretedRules(const ProgramState& st);

    std::size_t ruleCount() const override { return infos_.size(); }
    const rt::RuleInfo& info(std::size_t rule) const override { return infos_[rule]; }
    const std::vector<rt::SequenceEntry>& sequence() const override { return lowered_.sequence; }
    const std::vector<rt::CompoundInfo>& compounds() const override { return lowered_.compounds; }
    std::vector<rt::Value> compoundValues(std::size_t compound, rt::Match m, const rt::Graph& g, rt::Rng& rng) override;
    void findMatches(std::size_t rule, const rt::Graph& g, rt::MatchBuffer& out) override;
    void findAnchored(std::size_t rule, const rt::Graph& g, int node, rt::NodeId host, rt::MatchBuffer& out,
                      rt::EdgeId newEdgesFrom = rt::kNoId) override;
    void writeSet(std::size_t rule, std::size_t daughter, rt::Match m, rt::WriteSet& out) const override;
    void weigh(std::size_t rule, rt::Match m, const rt::Graph& g, std::vector<double>& weights) override;
    void prepare(std::size_t rule, std::size_t daughter, rt::Match m, const rt::Graph& g, rt::Rng& rng,
                 long long step) override;
    void commit(rt::Graph& g, long long step) override;
    void discard() override { pendingCount_ = 0; }
    const rt::AngleLayoutSpec* angleLayout() const override { return lowered_.angleLayout ? &*lowered_.angleLayout : nullptr; }
    bool hasDrawingCost() const override;
    double drawingCost(const rt::KindCounts& counts) override;
    double drawingTemperature() override;
    double checkedNumber(const ir::Expr& e, const rt::KindCounts* counts, double (*check)(double)) const;

    // The rule being applied when an EvalError escapes (for messages).
    const ir::Rule* currentRule() const { return current_; }

private:
    // The frame of rule r's expressions on match m (its locals cleared).
    EvalFrame matchFrame(const ir::Rule& r, rt::Match m, const rt::Graph& g, rt::Rng& rng);
    // One prepared application; kept in a pool so that its vectors are reused.
    struct Prepared {
        std::size_t rule = 0, daughter = 0;
        std::vector<rt::NodeId> nodes;                  // the match
        std::vector<rt::EdgeId> edges;
        std::vector<rt::FaceId> faces;
        std::vector<rt::Value> registers;               // the rewrite program's
        std::vector<LoopValues> loops;                  // and its loops'
    };

    // Calls onComplete() for every way to finish binding `ops` from
    // operation `i` on; stops early when it returns true.
    template <class OnComplete>
    bool search(const rt::Graph& g, const lower::MatchList& ops, std::size_t i, OnComplete& onComplete);
    template <class Each>
    static bool eachEdgeAt(const rt::Graph& g, rt::NodeId from, bool directed, bool outgoing, Each& each);
    void collect(const rt::Graph& g, const lower::MatchProgram& m, const lower::MatchList& ops, rt::MatchBuffer& out);
    bool orderedOk(const rt::Graph& g, int node, const std::vector<lower::OrderCheck>& checks) const;
    template <class OnComplete>
    bool bindFace(const rt::Graph& g, const lower::MatchFace& o, const lower::MatchList& ops, std::size_t i, OnComplete& onComplete);
    bool negativesHold(const rt::Graph& g, const lower::MatchProgram& m);
    // While findAnchored keeps only matches binding a new edge: false where
    // the lowering placed the test and no bound pattern edge is new.
    bool keptByNewEdgeGate(bool gateHere) const;

    const ProgramState& st_;
    const lower::LoweredProgram& lowered_;
    std::vector<rt::RuleInfo> infos_;   // the lowering's, with the weights of this run's parameters
    std::vector<Prepared> pending_;   // the first pendingCount_ are in use
    std::size_t pendingCount_ = 0;
    RewriteExecutor executor_;
    std::vector<rt::NodeId> boundNodes_;
    std::vector<rt::EdgeId> boundEdges_;
    std::vector<rt::FaceId> boundFaces_;
    rt::EdgeId newEdgesFrom_ = rt::kNoId;
    std::vector<rt::Value> locals_;
    // A frame reading the elements bound so far (conditions, near queries' centres).
    EvalFrame boundFrame(const rt::Graph& g);
    const ir::Rule* current_ = nullptr;
    std::size_t currentIndex_ = 0;   // current_'s index (near queries record under it)
};

}  // namespace g2d::interp
