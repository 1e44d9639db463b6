#pragma once
// Checks G^3's command lists: the grammar's `sequence { … }` and compound
// commands (`compound C { match { … } sequence { … } }`), whose entries name
// rules and compounds.
#include <map>
#include <string>
#include <vector>

#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

// `sequence { … }`: its entries (rules or compounds), by their indices.
void checkSequence(Globals& g, const ast::SequenceDecl& d, const std::map<std::string, int>& ruleIndex);
// A compound's match, as a rule (ir::Rule::compound) that binds one
// primitive; appends the compound (its entries come later).
void checkCompoundMatch(Globals& g, ExprChecker& ec, const ast::CompoundDecl& d);
// The compounds' entries (decls[i] is Program::compounds[i]), and no compound within itself.
void checkCompoundBodies(Globals& g, const std::vector<const ast::CompoundDecl*>& decls, const std::map<std::string, int>& ruleIndex);

// Compounds need a sequence; a compound or rule the sequence never reaches is reported.
void checkCommandListsReach(Globals& g);

}  // namespace g2d::sema
