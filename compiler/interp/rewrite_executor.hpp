#pragma once
// Executes a lowered rewrite program (lower::RewriteProgram) operation by
// operation: prepare reads the graph into registers, commit writes it. The
// rules' daughters and the axiom (a rewrite of the empty graph) both run here.
#include <optional>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/match_set.hpp"
#include "interp/evaluator.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::interp {

// What prepare keeps of one `for` loop (lower::LoopProgram) until commit:
// the face's corners, one per turn, and each turn's registers, one after the other.
struct LoopValues {
    std::vector<rt::NodeId> corners;
    std::vector<rt::Value> registers;
    std::vector<rt::NodeId> made;      // after commit: each turn's new nodes (turn t's node i at t * localNodes + i)
};

class RewriteExecutor {
public:
    // `f` is the frame of the rewrite's expressions (match, locals, generator);
    // `registers` must hold p.registers.size() values; `loops`, one per loop, is filled.
    void prepare(const lower::RewriteProgram& p, rt::Match m, const rt::Graph& g, EvalFrame& f,
                 std::vector<rt::Value>& registers, std::vector<LoopValues>& loops);
    // `m` is the match prepare saw (the graph changes only here).
    void commit(const lower::RewriteProgram& p, rt::Match m, std::vector<rt::Value>& registers, std::vector<LoopValues>& loops,
                rt::Graph& g, long long step);

private:
    void place(const lower::Place& o, rt::Match m, const rt::Graph& g);
    static rt::Value evaluatePosition(const lower::EvalPosition& o, EvalFrame& f);
    void prepareLoop(const lower::LoopProgram& l, rt::Match m, const rt::Graph& g, EvalFrame& f, LoopValues& out);
    void ringCorners(const lower::CreateRingFace& o, const lower::LoopProgram& l, const LoopValues& values);
    // The operations `ops` on the handles in hostOf_, edgeOf_, faceOf_.
    void apply(const std::vector<lower::CommitOp>& ops, rt::Match m, std::vector<rt::Value>& registers, rt::Graph& g,
               long long step, const lower::RewriteProgram& p, std::vector<LoopValues>& loops);
    void commitLoop(const lower::LoopProgram& l, LoopValues& values, rt::Graph& g, long long step, const lower::RewriteProgram& p,
                    std::vector<LoopValues>& loops);
    void split(const lower::SplitProgram& s, rt::FaceId face, const std::vector<rt::Value>& registers, rt::Graph& g, long long step,
               const lower::RewriteProgram& p, std::vector<LoopValues>& loops);

    std::vector<std::optional<rt::Value>> placed_;  // automatic positions (vec2 or vec3), by daughter node
    std::vector<rt::NodeId> hostOf_;   // the rewrite's node handles
    std::vector<rt::EdgeId> edgeOf_;   // and edge handles
    std::vector<rt::FaceId> faceOf_;   // and face handles
    std::vector<rt::NodeId> corners_;  // a new face's
    std::vector<rt::NodeId> turnNodes_;   // a loop's new nodes, turn by turn
    std::vector<rt::NodeId> loopFrame_;   // the match's nodes and a turn's corners, for its expressions
};

}  // namespace g2d::interp
