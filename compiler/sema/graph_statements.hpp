#pragma once
// What the axiom, the match and the daughters check alike: kinds by name,
// edge arrows, face corners, repeated names, attribute and style
// assignments, sketch positions.
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

// Looks up a kind by name, requiring the given class; reports otherwise (-1).
int resolveKind(Globals& g, const ast::Ident& name, ir::ElemClass cls);
// The arrow must agree with how the edge kind was declared.
bool checkArrow(Globals& g, const ast::EdgeStmt& e, int kind);
// Whether the expression reads an automatic position (`placed`).
bool usesPlaced(const ir::Expr& e);

inline const ast::NodeStmt* asNode(const ast::GraphStmt& s) { return std::get_if<ast::NodeStmt>(&s.stmt); }
inline const ast::EdgeStmt* asEdge(const ast::GraphStmt& s) { return std::get_if<ast::EdgeStmt>(&s.stmt); }
inline const ast::FaceStmt* asFace(const ast::GraphStmt& s) { return std::get_if<ast::FaceStmt>(&s.stmt); }

// A face's corner, once: reports a name seen before in `seen` (a face's
// corners are distinct nodes) and returns false then.
bool firstTimeCorner(Globals& g, std::map<std::string, Span>& seen, const ast::Ident& c);
// `Kind(all t)` outside a daughter (`where`: "the axiom", "a match"): reported; true when `f` is one.
bool ringOutsideDaughter(Globals& g, const ast::FaceStmt& f, const char* where);
void reportDuplicate(Globals& g, const ast::Ident& name, Span previous);
// Checks `{ attr = expr, style.prop = expr }` against a kind.
void checkAssignments(Globals& g, ExprChecker& ec, int kind, const std::vector<ast::Assignment>& assigns,
                      const ExprEnv& env, std::vector<ir::AttrAssign>& attrsOut,
                      std::vector<ir::StyleAssign>& stylesOut, std::optional<ir::Expr>* radiusOut = nullptr);
std::optional<ir::Vec2> sketchOf(const ast::NodeStmt& n);

}  // namespace g2d::sema
