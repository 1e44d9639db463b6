#include "lsp/symbol_index.hpp"

#include <algorithm>
#include <functional>
#include <set>

namespace g2d::lsp {

namespace {

std::string trimmed(std::string s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t\r");
    s = s.substr(b, e - b + 1);
    if (s.size() > 200) s = s.substr(0, 200) + "…";
    return s;
}

// Spans compare as (line, col) pairs.
bool before(std::uint32_t l1, std::uint32_t c1, std::uint32_t l2, std::uint32_t c2) {
    return l1 < l2 || (l1 == l2 && c1 < c2);
}

}  // namespace

bool SymbolIndex::contains(const Span& s, FileId file, std::uint32_t line, std::uint32_t col) {
    if (!s.valid() || s.file != file) return false;
    const std::uint32_t endLine = s.endLine ? s.endLine : s.line;
    const std::uint32_t endCol = s.endCol ? s.endCol : s.col + 1;
    return !before(line, col, s.line, s.col) && before(line, col, endLine, endCol + 1);
}

const char* SymbolIndex::describe(SymbolKind kind) {
    switch (kind) {
    case SymbolKind::NodeKind: return "node kind";
    case SymbolKind::EdgeKind: return "edge kind";
    case SymbolKind::FaceKind: return "face kind";
    case SymbolKind::Face: return "face";
    case SymbolKind::Attribute: return "attribute";
    case SymbolKind::Rule: return "production";
    case SymbolKind::Function: return "function";
    case SymbolKind::FnParam: return "function parameter";
    case SymbolKind::Param: return "parameter";
    case SymbolKind::Const: return "constant";
    case SymbolKind::Enum: return "enum";
    case SymbolKind::Enumerator: return "enumerator";
    case SymbolKind::PatternNode: return "matched node";
    case SymbolKind::PatternEdge: return "matched edge";
    case SymbolKind::DaughterNode: return "daughter node";
    case SymbolKind::DaughterEdge: return "daughter edge";
    case SymbolKind::AxiomNode: return "axiom node";
    case SymbolKind::Let: return "let binding";
    case SymbolKind::Import: return "import";
    }
    return "name";
}

void SymbolIndex::add(SymbolKind kind, const ast::Ident& name, Span scope, std::string container, std::string typeName) {
    if (name.name.empty() || !name.span.valid()) return;
    Symbol s{name.name, kind, name.span, scope, std::move(container), std::move(typeName),
             trimmed(sources_.lineText(name.span.file, name.span.line))};
    symbols_.push_back(std::move(s));
}

void SymbolIndex::graphStmt(const ast::GraphStmt& g, SymbolKind nodeKind, SymbolKind edgeKind, Span scope,
                            const std::string& rule) {
    if (const auto* n = std::get_if<ast::NodeStmt>(&g.stmt)) {
        // `x;` or `x at …` refers to an existing name: not a declaration.
        if (n->kind || n->wildcard) add(nodeKind, n->name, scope, rule, n->wildcard ? "*" : n->kind->name);
    } else if (const auto* e = std::get_if<ast::EdgeStmt>(&g.stmt)) {
        if (e->name && !e->kind.name.empty()) add(edgeKind, *e->name, scope, rule, e->kind.name);
    } else if (const auto* f = std::get_if<ast::FaceStmt>(&g.stmt)) {
        if (f->name) add(SymbolKind::Face, *f->name, scope, rule, f->kind.name);
    }
}

void SymbolIndex::matchStmts(const std::vector<ast::MatchStmt>& body, Span scope, const std::string& rule) {
    for (const auto& m : body) {
        if (const auto* g = std::get_if<ast::GraphStmt>(&m.stmt))
            graphStmt(*g, SymbolKind::PatternNode, SymbolKind::PatternEdge, scope, rule);
        else if (const auto* nac = std::get_if<ast::NacBlock>(&m.stmt))
            matchStmts(nac->body, nac->span, rule);
    }
}

SymbolIndex::SymbolIndex(const std::vector<ast::Program>& files, const SourceManager& sources) : sources_(sources) {
    for (const auto& file : files) {
        for (const auto& decl : file.decls) {
            std::visit(
                [&](const auto& d) {
                    using T = std::decay_t<decltype(d)>;
                    if constexpr (std::is_same_v<T, ast::SpaceDecl>) {
                        space3d_ = space3d_ || d.dimensions == 3;
                    } else if constexpr (std::is_same_v<T, ast::KindDecl>) {
                        add(d.cls == ast::KindDecl::Class::Edge ? SymbolKind::EdgeKind : d.cls == ast::KindDecl::Class::Face ? SymbolKind::FaceKind : SymbolKind::NodeKind, d.name, Span{});
                        for (const auto& a : d.attrs) add(SymbolKind::Attribute, a.name, Span{}, d.name.name, a.type.name.name);
                    } else if constexpr (std::is_same_v<T, ast::RuleDecl>) {
                        add(SymbolKind::Rule, d.name, Span{});
                        matchStmts(d.match, d.span, d.name.name);
                        for (const auto& item : d.items) {
                            if (const auto* let = std::get_if<ast::LetStmt>(&item.item)) {
                                add(SymbolKind::Let, let->name, d.span, d.name.name, let->type ? let->type->name.name : "");
                            } else if (const auto* block = std::get_if<ast::ProduceBlock>(&item.item)) {
                                // A `for` loop's variables and nodes are visible in its body.
                                std::function<void(const std::vector<ast::ProduceStmt>&, Span)> body =
                                    [&](const std::vector<ast::ProduceStmt>& stmts, Span scope) {
                                        for (const auto& ps : stmts) {
                                            if (const auto* let = std::get_if<ast::LetStmt>(&ps.stmt))
                                                add(SymbolKind::Let, let->name, scope, d.name.name,
                                                    let->type ? let->type->name.name : "");
                                            else if (const auto* g = std::get_if<ast::GraphStmt>(&ps.stmt))
                                                graphStmt(*g, SymbolKind::DaughterNode, SymbolKind::DaughterEdge, scope,
                                                          d.name.name);
                                            else if (const auto* split = std::get_if<ast::SplitStmt>(&ps.stmt)) {
                                                if (split->var) add(SymbolKind::DaughterNode, *split->var, split->span, d.name.name);
                                            } else if (const auto* loop = std::get_if<ast::ForBlock>(&ps.stmt)) {
                                                for (const auto& v : loop->vars) add(SymbolKind::DaughterNode, v, loop->span, d.name.name);
                                                body(loop->body, loop->span);
                                            }
                                        }
                                    };
                                body(block->body, block->span);
                            }
                        }
                    } else if constexpr (std::is_same_v<T, ast::CompoundDecl>) {
                        add(SymbolKind::Rule, d.match.name, Span{});   // a sequence names it as it names a rule
                        matchStmts(d.match.match, d.span, d.match.name.name);
                    } else if constexpr (std::is_same_v<T, ast::SequenceDecl>) {
                        if (d.name) add(SymbolKind::Rule, *d.name, Span{});   // a named list: lists name it as they name a rule
                    } else if constexpr (std::is_same_v<T, ast::FnDecl>) {
                        add(SymbolKind::Function, d.name, Span{}, "", d.result.name.name);
                        for (const auto& p : d.params) add(SymbolKind::FnParam, p.name, d.span, d.name.name, p.type.name.name);
                    } else if constexpr (std::is_same_v<T, ast::ParamDecl>) {
                        add(SymbolKind::Param, d.name, Span{}, "", d.type.name.name);
                    } else if constexpr (std::is_same_v<T, ast::ConstDecl>) {
                        add(SymbolKind::Const, d.name, Span{}, "", d.type ? d.type->name.name : "");
                    } else if constexpr (std::is_same_v<T, ast::EnumDecl>) {
                        add(SymbolKind::Enum, d.name, Span{});
                        for (const auto& v : d.values) add(SymbolKind::Enumerator, v, Span{}, d.name.name);
                    } else if constexpr (std::is_same_v<T, ast::AxiomDecl>) {
                        for (const auto& g : d.body)
                            graphStmt(g, SymbolKind::AxiomNode, SymbolKind::AxiomNode, d.span, "axiom");
                    }
                },
                decl.decl);
        }
    }
    // `f: Room;` in a match, Room a face kind, declares a face (of any corner count).
    std::set<std::string> faceKinds;
    for (const auto& s : symbols_)
        if (s.kind == SymbolKind::FaceKind) faceKinds.insert(s.name);
    for (auto& s : symbols_)
        if (s.kind == SymbolKind::PatternNode && faceKinds.count(s.typeName)) s.kind = SymbolKind::Face;
}

std::vector<const Symbol*> SymbolIndex::visible(FileId file, std::uint32_t line, std::uint32_t col) const {
    std::vector<const Symbol*> locals, globals;
    for (const auto& s : symbols_) {
        if (!s.scope.valid()) {
            if (s.kind != SymbolKind::Attribute) globals.push_back(&s);
        } else if (contains(s.scope, file, line, col)) {
            locals.push_back(&s);
        }
    }
    // Innermost scope first (a negative condition's names before the rule's).
    std::stable_sort(locals.begin(), locals.end(), [](const Symbol* a, const Symbol* b) {
        return before(b->scope.line, b->scope.col, a->scope.line, a->scope.col);
    });
    locals.insert(locals.end(), globals.begin(), globals.end());
    return locals;
}

const Symbol* SymbolIndex::resolve(const std::string& name, FileId file, std::uint32_t line, std::uint32_t col,
                                   const std::string& receiver) const {
    if (!receiver.empty()) {
        // `x.attr`: the attribute of x's kind, if x is known; else any attribute of that name.
        std::string kind;
        if (const Symbol* r = resolve(receiver, file, line, col)) kind = r->typeName;
        const Symbol* any = nullptr;
        for (const auto& s : symbols_) {
            if (s.kind != SymbolKind::Attribute || s.name != name) continue;
            if (s.container == kind) return &s;
            if (!any) any = &s;
        }
        return any;
    }
    for (const Symbol* s : visible(file, line, col))
        if (s->name == name) return s;
    return nullptr;
}

}  // namespace g2d::lsp
