#pragma once
// The lowering's one product: everything both back ends need to run a
// program, made once per program by lowerProgram. The interpreter executes
// it and the emitter prints it; neither calls the lowering's functions
// itself. The ir::Program stays the owner of what the operations point at
// (expressions, kinds, names) and must outlive this.
#include <optional>
#include <vector>

#include "g2d/angle_step.hpp"
#include "g2d/command_list.hpp"
#include "lower/match_program.hpp"
#include "lower/rewrite_program.hpp"
#include "lower/rule_facts.hpp"
#include "lower/run_values.hpp"
#include "lower/start_program.hpp"

namespace g2d::lower {

struct LoweredRule {
    const ir::Rule* rule = nullptr;
    MatchProgram match;
    std::vector<RewriteProgram> daughters;
    RuleFacts facts;
};

struct LoweredProgram {
    const ir::Program* ir = nullptr;
    StartProgram start;
    std::vector<LoweredRule> rules;
    std::vector<rt::SequenceEntry> sequence;        // the `sequence` (empty: the priorities alone)
    std::vector<rt::CompoundInfo> compounds;
    std::vector<CompoundLets> compoundLets;         // per compound
    std::optional<rt::AngleLayoutSpec> angleLayout;   // null without `layout angles`
};

LoweredProgram lowerProgram(const ir::Program& prog);

}  // namespace g2d::lower
