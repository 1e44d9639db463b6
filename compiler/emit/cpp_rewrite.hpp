#pragma once
// Prints a lowered rewrite program (lower::RewriteProgram) as C++, one
// operation at a time: the prepare part evaluates into constants r0, r1, …
// (with `placed`, the automatic positions); the commit part writes graph `G`
// at `step`, reading the match `m` and the registers by the same names. The
// rules' daughters and the axiom are printed here.
#include <string>

#include "emit/cpp_expr.hpp"
#include "lower/rewrite_program.hpp"

namespace g2d::emit {

class RewritePrinter {
public:
    RewritePrinter(const ir::Program& prog, ExprGen& gen, Places& places, ConstantValues& constants)
        : prog_(prog), gen_(gen), places_(places), constants_(constants) {}

    std::string prepare(const lower::RewriteProgram& p, const ExprContext& ctx, const std::string& in);
    std::string commit(const lower::RewriteProgram& p, const std::string& in);

    static std::string reg(int r) { return "r" + std::to_string(r); }

private:
    std::string placement(const lower::Place& o, const std::string& in);
    std::string styleValue(const lower::Operand& v);
    std::string record(int kind, const std::vector<lower::AttrWrite>& attrs, const std::string& element, ir::ElemClass cls,
                       const std::string& c) const;

    const ir::Program& prog_;
    ExprGen& gen_;
    Places& places_;
    ConstantValues& constants_;
};

}  // namespace g2d::emit
