#pragma once
// Checks G^3's command lists: the grammar's `sequence { … }` and compound
// commands (`compound C { match { … } sequence { … } }`), whose entries name
// rules and compounds.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

// What a command list's names can be, and the named lists written out
// (G^3 §2.4.6: a list that names another takes its commands in).
class CommandLists {
public:
    // `rules`: rules by name (a compound by its match rule's); `named`: every `sequence NAME { … }`.
    CommandLists(Globals& g, ExprChecker& ec, const std::map<std::string, int>& rules, std::vector<const ast::SequenceDecl*> named);
    // The entries of a list's items, named lists written out, repeats as
    // SequenceEntry::Kind::Repeat headers.
    std::vector<ir::SequenceEntry> entries(const ast::SequenceDecl& d);
    // A named list that no list names never runs.
    void warnUnused() const;

private:
    void expand(const std::vector<ast::SequenceItem>& items, std::vector<ir::SequenceEntry>& out);
    void repeat(const ast::SequenceItem& item, std::vector<ir::SequenceEntry>& out);
    // A named list's entries (written out once; empty when it contains itself).
    const std::vector<ir::SequenceEntry>& list(const ast::SequenceDecl& d, const ast::Ident& at);

    Globals& g_;
    ExprChecker& ec_;
    const std::map<std::string, int>& rules_;
    std::map<std::string, const ast::SequenceDecl*> named_;
    std::map<std::string, std::vector<ir::SequenceEntry>> done_;
    std::vector<std::string> open_;                        // the lists being written out, outermost first
    std::map<const ast::SequenceItem*, int> counts_;       // each repeat's Program::repeatCounts index
    std::set<std::string> used_;
    std::set<std::string> cycles_;                          // lists reported as containing themselves
    bool tooLong_ = false;
};

// `sequence { … }`: its entries (rules, compounds, repeats).
void checkSequence(Globals& g, const ast::SequenceDecl& d, CommandLists& lists);
// A compound's match, as a rule (ir::Rule::compound) that binds one
// primitive; appends the compound (its entries come later).
void checkCompoundMatch(Globals& g, ExprChecker& ec, const ast::CompoundDecl& d);
// The compounds' entries (decls[i] is Program::compounds[i]), and no compound within itself.
void checkCompoundBodies(Globals& g, const std::vector<const ast::CompoundDecl*>& decls, CommandLists& lists);

// Compounds need a sequence; a compound or rule the sequence never reaches is reported.
void checkCommandListsReach(Globals& g);

}  // namespace g2d::sema
