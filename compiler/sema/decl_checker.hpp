#pragma once
// Checks top-level declarations other than the axiom and rules.
#include <set>
#include <string>

#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

// The built-in value types by name ("int", …, "vec3").
const std::set<std::string>& valueTypeNames();
// Facts an attribute must not be named after (declaring one is an error).
const std::set<std::string>& reservedAttributeNames();
// Resolves a type name (a built-in value type or an enum).
std::optional<ir::Type> resolveType(Globals& g, const ast::TypeRef& t);

// Registers a top-level name; reports a duplicate and returns false if taken.
bool declareTopLevel(Globals& g, const ast::Ident& name, const std::string& what);

void declareEnum(Globals& g, const ast::EnumDecl& d);
void declareKindName(Globals& g, const ast::KindDecl& d);
void checkParam(Globals& g, ExprChecker& ec, const ast::ParamDecl& d);
void checkConst(Globals& g, ExprChecker& ec, const ast::ConstDecl& d);
void checkFunction(Globals& g, ExprChecker& ec, const ast::FnDecl& d);
void checkKindBody(Globals& g, ExprChecker& ec, const ast::KindDecl& d);
void checkLimit(Globals& g, ExprChecker& ec, const ast::LimitDecl& d, bool& seen);
// A step limit's value (global, a priority's, a rule's): an int of literals,
// constants and parameters, not negative when known. Null after an error.
std::optional<ir::Expr> checkStepLimit(Globals& g, ExprChecker& ec, const ast::Expr& value);
// The same for any count (`what`: "a step limit", "a repeat count").
std::optional<ir::Expr> checkCount(Globals& g, ExprChecker& ec, const ast::Expr& value, const std::string& what);
// `merge within T;` (a constant float, not negative).
void checkMerge(Globals& g, ExprChecker& ec, const ast::MergeDecl& d);
void checkPriority(Globals& g, ExprChecker& ec, const ast::PriorityDecl& d);

// Style property values that are checked when constant.
void checkStyleValue(Globals& g, const std::string& prop, const ir::Expr& value);

}  // namespace g2d::sema
