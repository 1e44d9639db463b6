#include "lsp/completion.hpp"

#include <set>

#include "front/reserved_names.hpp"
#include "sema/builtins.hpp"
#include "sema/element_facts.hpp"

namespace g2d::lsp {

namespace {

int completionKindNumber(SymbolKind k) {   // LSP CompletionItemKind
    switch (k) {
    case SymbolKind::NodeKind: return 7;       // Class
    case SymbolKind::EdgeKind: return 22;      // Struct
    case SymbolKind::FaceKind: return 22;      // Struct
    case SymbolKind::Face: return 6;           // Variable
    case SymbolKind::Attribute: return 10;     // Property
    case SymbolKind::Function: return 3;       // Function
    case SymbolKind::Const: return 21;         // Constant
    case SymbolKind::Enum: return 13;          // Enum
    case SymbolKind::Enumerator: return 20;    // EnumMember
    default: return 6;                         // Variable
    }
}

}  // namespace

std::vector<CompletionItem> completionsAt(const SymbolIndex& index, FileId file, std::uint32_t line, std::uint32_t col,
                                          const std::string& receiver) {
    std::vector<CompletionItem> items;
    std::set<std::string> seen;
    auto add = [&](const std::string& label, int kind, const std::string& detail) {
        if (seen.insert(label).second) items.push_back({label, kind, detail});
    };
    if (!receiver.empty()) {
        // After `x.`: x's attributes (all attributes if x's kind is unknown),
        // and the facts of its class (an edge has no position).
        std::string kind;
        ir::ElemClass cls = ir::ElemClass::Node;
        if (const Symbol* r = index.resolve(receiver, file, line, col)) {
            kind = r->typeName;
            if (r->kind == SymbolKind::PatternEdge || r->kind == SymbolKind::DaughterEdge) cls = ir::ElemClass::Edge;
            if (r->kind == SymbolKind::Face) cls = ir::ElemClass::Face;
        }
        for (const auto& s : index.all())
            if (s.kind == SymbolKind::Attribute && (kind.empty() || s.container == kind))
                add(s.name, 10, s.typeName + " (" + s.container + ")");
        for (const auto& f : sema::elementFacts())
            if (sema::hasFact(f, cls, index.space3d())) add(f.name, 10, f.meaning);
        return items;
    }
    for (const Symbol* s : index.visible(file, line, col))
        if (s->kind != SymbolKind::Rule) add(s->name, completionKindNumber(s->kind), SymbolIndex::describe(s->kind));
    for (const auto& b : sema::builtinFunctions()) add(b.name, 3, b.signature);
    for (const auto& k : front::keywords()) add(k, 14, "keyword");
    return items;
}

}  // namespace g2d::lsp
