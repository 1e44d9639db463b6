#pragma once
// What an editor needs to know about the names of a grammar: every
// declaration (kinds, attributes, productions, functions and their
// parameters, parameters, constants, enums, pattern and daughter elements,
// `let` bindings, imports) with where it is, the part of the file where it
// is visible, and the line that declares it. Built from the syntax trees, so
// it works even when the grammar has errors.
#include <string>
#include <vector>

#include "ast/ast.hpp"
#include "diag/source.hpp"

namespace g2d::lsp {

enum class SymbolKind {
    NodeKind, EdgeKind, FaceKind, Face, Attribute, Rule, Function, FnParam, Param, Const, Enum, Enumerator,
    PatternNode, PatternEdge, DaughterNode, DaughterEdge, AxiomNode, Let, Import
};

struct Symbol {
    std::string name;
    SymbolKind kind;
    Span at;             // where the name is written
    Span scope;          // where it is visible (invalid: the whole grammar)
    std::string container;  // the kind of an attribute, the enum of an enumerator, the rule of a local
    std::string typeName;   // a pattern element's kind, an attribute's or parameter's type
    std::string declaration;  // the declaring line, trimmed
};

class SymbolIndex {
public:
    SymbolIndex(const std::vector<ast::Program>& files, const SourceManager& sources);

    const std::vector<Symbol>& all() const { return symbols_; }
    bool space3d() const { return space3d_; }   // the files declare `space 3d;`
    // The declaration `name` refers to at (file, line, col), innermost scope
    // first; for `receiver.name`, the attribute of the receiver's kind.
    const Symbol* resolve(const std::string& name, FileId file, std::uint32_t line, std::uint32_t col,
                          const std::string& receiver = "") const;
    // Symbols visible at a position (locals of the enclosing scopes, then globals).
    std::vector<const Symbol*> visible(FileId file, std::uint32_t line, std::uint32_t col) const;
    static bool contains(const Span& s, FileId file, std::uint32_t line, std::uint32_t col);
    static const char* describe(SymbolKind kind);

private:
    bool space3d_ = false;
    void add(SymbolKind kind, const ast::Ident& name, Span scope, std::string container = "", std::string typeName = "");
    void graphStmt(const ast::GraphStmt& g, SymbolKind nodeKind, SymbolKind edgeKind, Span scope, const std::string& rule);
    void matchStmts(const std::vector<ast::MatchStmt>& body, Span scope, const std::string& rule);

    const SourceManager& sources_;
    std::vector<Symbol> symbols_;
};

}  // namespace g2d::lsp
