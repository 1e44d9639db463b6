#include "sema/sema.hpp"

#include "sema/canvas_checker.hpp"
#include "sema/decl_checker.hpp"
#include "sema/graph_checker.hpp"
#include "sema/layout_checker.hpp"
#include "sema/lint.hpp"
#include "sema/sequence_checker.hpp"

namespace g2d {

using namespace sema;

std::optional<ir::Program> analyze(const std::vector<const ast::Program*>& programs, Diagnostics& diags) {
    ir::Program prog;
    Globals g(prog, diags);
    if (!programs.empty()) g.mainFile = programs.back()->file;
    ExprChecker ec(g);
    const std::size_t errorsBefore = diags.errorCount();

    auto each = [&](auto&& fn) {
        for (const auto* p : programs)
            for (const auto& d : p->decls) std::visit(fn, d.decl);
    };
    // The space first: it decides the type of every position.
    const ast::SpaceDecl* space = nullptr;
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::SpaceDecl>) {
            if (space && space->dimensions != d.dimensions) {
                auto& diag = diags.error(d.span, "the grammar is declared both 2D and 3D");
                diag.notes.push_back({space->span, "the first declaration is here"});
            } else if (!space) {
                space = &d;
                prog.space3d = d.dimensions == 3;
            }
        }
    });
    // Types next: enums and kind names may be used before their declaration.
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::EnumDecl>) declareEnum(g, d);
        else if constexpr (std::is_same_v<T, ast::KindDecl>) declareKindName(g, d);
    });
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::ParamDecl> || std::is_same_v<T, ast::ConstDecl>)
            g.laterValues.emplace(d.name.name, d.name.span);
        else if constexpr (std::is_same_v<T, ast::FnDecl>) g.laterFunctions.emplace(d.name.name, d.name.span);
    });
    // Parameters, constants and functions in order: each sees only those declared before it.
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::ParamDecl>) checkParam(g, ec, d);
        else if constexpr (std::is_same_v<T, ast::ConstDecl>) checkConst(g, ec, d);
        else if constexpr (std::is_same_v<T, ast::FnDecl>) checkFunction(g, ec, d);
    });
    g.constsDeclared = static_cast<int>(prog.consts.size());
    g.functionsDeclared = static_cast<int>(prog.functions.size());
    std::vector<const ast::KindDecl*> kindDecls;
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::KindDecl>) {
            checkKindBody(g, ec, d);
            checkEdgeLayout(g, ec, d);
            kindDecls.push_back(&d);
        }
    });
    // Compound names, so that `C.name` outside a rule gets a clear message (their lets come later).
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::CompoundDecl>) g.compounds.emplace(d.match.name.name, -1);
    });
    bool limitSeen = false;
    const ast::AxiomDecl* axiom = nullptr;
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::LimitDecl>) {
            checkLimit(g, ec, d, limitSeen);
        } else if constexpr (std::is_same_v<T, ast::MergeDecl>) {
            checkMerge(g, ec, d);
        } else if constexpr (std::is_same_v<T, ast::LayoutDecl>) {
            checkLayoutDecl(g, ec, d);
        } else if constexpr (std::is_same_v<T, ast::CanvasDecl>) {
            checkCanvas(g, ec, d);
        } else if constexpr (std::is_same_v<T, ast::PriorityDecl>) {
            checkPriority(g, ec, d);
        } else if constexpr (std::is_same_v<T, ast::DefsDecl>) {
            prog.svgDefs.push_back(d.svg);
        } else if constexpr (std::is_same_v<T, ast::AxiomDecl>) {
            if (axiom) {
                auto& diag = diags.error(d.span, "a grammar has exactly one axiom, but this is a second one");
                diag.notes.push_back({axiom->span, "the first axiom is here"});
            } else {
                axiom = &d;
                checkAxiom(g, ec, d);
            }
        }
    });
    if (!axiom && !programs.empty()) {
        Span at{programs.back()->file, 0, 0, 0, 0};
        diags.error(at, "the grammar has no `axiom { … }`: there is no graph to start from");
    }
    // Compounds first: rules read their lets (`C.name`).
    std::map<std::string, std::pair<Span, const char*>> ruleNames;   // and what it names
    std::vector<const ast::CompoundDecl*> compounds;
    auto claimName = [&](const ast::Ident& name, const char* what) {
        if (auto [it, inserted] = ruleNames.emplace(name.name, std::pair{name.span, what}); !inserted) {
            auto& diag = diags.error(name.span, std::string("a ") + it->second.second + " named `" + name.name + "` already exists");
            diag.notes.push_back({it->second.first, "the first one is here"});
        }
    };
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::CompoundDecl>) {
            claimName(d.match.name, "compound");
            checkCompoundMatch(g, ec, d);
            compounds.push_back(&d);
        }
    });
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::RuleDecl>) {
            claimName(d.name, "rule");
            checkRule(g, ec, d);
        }
    });
    std::map<std::string, int> ruleIndex;
    for (std::size_t r = 0; r < prog.rules.size(); ++r) ruleIndex.emplace(prog.rules[r].name, static_cast<int>(r));
    std::vector<const ast::SequenceDecl*> namedLists;
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::SequenceDecl>)
            if (d.name) {
                claimName(*d.name, "sequence");
                namedLists.push_back(&d);
            }
    });
    CommandLists lists(g, ec, ruleIndex, namedLists);
    each([&](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, ast::SequenceDecl>)
            if (!d.name) checkSequence(g, d, lists);
    });
    checkCompoundBodies(g, compounds, lists);
    lists.warnUnused();
    checkAngleLayoutUse(g, kindDecls);
    if (diags.errorCount() == errorsBefore) checkCommandListsReach(g);
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    lintProgram(g);
    return prog;
}

}  // namespace g2d
