#pragma once
// What a run does before its first step, decided once for both back ends:
// the constants in declaration order, then each kind's attribute defaults in
// declaration order (both may draw from the generator, so the order is part
// of the result), then the axiom, which is a rewrite of the empty graph
// (lower::RewriteProgram with no match: prepare evaluates every value, in
// the order the axiom is written; commit creates its nodes and edges).
#include <variant>
#include <vector>

#include "lower/rewrite_program.hpp"

namespace g2d::lower {

struct InitConst {          // constant `index`: its folded literal, or its value evaluated now
    int index;
    const ir::Const* decl;
};
struct InitDefault {        // the default of attribute `attr` of kind `kind`
    int kind, attr;
    const ir::Expr* value;
};
using InitOp = std::variant<InitConst, InitDefault>;

struct StartProgram {
    std::vector<InitOp> init;
    RewriteProgram axiom;       // CreateNode::posReg < 0: the origin (a node written without `at`)
};

StartProgram lowerStart(const ir::Program& prog);

}  // namespace g2d::lower
