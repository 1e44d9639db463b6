#pragma once
// Type-checks AST expressions and lowers them to typed IR expressions.
#include <optional>

#include "diag/suggest.hpp"
#include "sema/context.hpp"

namespace g2d::sema {

class ExprChecker {
public:
    explicit ExprChecker(Globals& g) : g_(g) {}

    // Reports problems and returns nothing when the expression is invalid
    // (callers then skip checks that depend on it, avoiding cascades).
    std::optional<ir::Expr> check(const ast::Expr& e, const ExprEnv& env);
    // As check(), then requires `expected` (an int is accepted where a float is
    // expected). `what` names the expression for the message.
    std::optional<ir::Expr> checkAs(const ast::Expr& e, ir::Type expected, const ExprEnv& env,
                                    const std::string& what);

    // Inserts the implicit int → float conversion.
    static ir::Expr coerce(ir::Expr e, ir::Type to);

private:
    std::optional<ir::Expr> name(const ast::Expr& e, const ast::Name& n, const ExprEnv& env);
    std::optional<ir::Expr> member(const ast::Expr& e, const ast::Member& m, const ExprEnv& env);
    std::optional<ir::Expr> compoundValue(const ast::Expr& e, int compound, const ast::Ident& member, const ExprEnv& env);
    std::optional<ir::Expr> elementMember(const ast::Expr& e, const ElemBinding& b, const ast::Ident& member,
                                          const ExprEnv& env);
    std::optional<ir::Expr> call(const ast::Expr& e, const ast::Call& c, const ExprEnv& env);
    std::optional<ir::Expr> count(const ast::Expr& e, const ast::Call& c, const ExprEnv& env);
    std::optional<ir::Expr> unary(const ast::Expr& e, const ast::Unary& u, const ExprEnv& env);
    std::optional<ir::Expr> binary(const ast::Expr& e, const ast::Binary& b, const ExprEnv& env);
    std::optional<ir::Expr> conditional(const ast::Expr& e, const ast::Conditional& c, const ExprEnv& env);
    bool checkFormatTemplate(const ast::Expr& templ, std::size_t valueCount);

    std::string tn(const ir::Type& t) const { return g_.typeName(t); }

    Globals& g_;
};

}  // namespace g2d::sema
