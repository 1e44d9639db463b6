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
    // A loop's turn registers, and the names of its turn record (a struct
    // `Turn_<names>_L` holding u, v and them) and of the array of those
    // records (`turns_<names>_L_`), which the rule's code declares; the
    // pending record holds `loopFirstL` and `loopCountL`.
    static std::string loopReg(int loop, int r) { return "l" + std::to_string(loop) + "r" + std::to_string(r); }
    void setLoopNames(std::string names) { loopNames_ = std::move(names); }

private:
    std::string prepareOps(const std::vector<lower::PrepareOp>& ops, const lower::RewriteProgram& p, const ExprContext& ctx,
                           const std::string& in);
    std::string commitOps(const std::vector<lower::CommitOp>& ops, const lower::RewriteProgram& p, const std::string& c);
    std::string prepareLoop(int loop, const lower::RewriteProgram& p, const ExprContext& ctx, const std::string& in);
    std::string commitLoop(int loop, const lower::RewriteProgram& p, const std::string& c);
    std::string splitFace(const lower::SplitFace& o, const lower::RewriteProgram& p, const std::string& c);
    std::string ringFace(const lower::CreateRingFace& o, const lower::RewriteProgram& p, const std::string& c);
    std::string regName(int r) const { return regPrefix_ + std::to_string(r); }
    std::string attrValue(const lower::Operand& v) const;
    std::string position(int posReg) const;
    std::string regPrefix_ = "r";   // "lLr" in loop L's operations
    std::string loopNames_;
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
