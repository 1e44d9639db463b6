#include "sema/sequence_checker.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "sema/graph_checker.hpp"
#include "diag/suggest.hpp"

namespace g2d::sema {

namespace {

// A list's names, each a rule or a compound.
std::vector<ir::SequenceEntry> entries(Globals& g, const ast::SequenceDecl& d, const std::map<std::string, int>& ruleIndex) {
    std::vector<std::string> names;
    for (const auto& [name, index] : ruleIndex) names.push_back(name);
    std::vector<ir::SequenceEntry> out;
    for (const auto& r : d.rules) {
        auto it = ruleIndex.find(r.name);
        if (it == ruleIndex.end()) {
            g.diags.error(r.span, "no rule or compound named `" + r.name + "`" + suggest(r.name, names));
            continue;
        }
        const int compound = g.prog.rules[static_cast<std::size_t>(it->second)].compound;
        out.push_back(compound >= 0 ? ir::SequenceEntry{true, compound} : ir::SequenceEntry{false, it->second});
    }
    if (d.rules.empty()) g.diags.error(d.span, "an empty `sequence` would apply nothing; list rules, each followed by `;`");
    return out;
}

// What a compound's match binds, when it is one primitive (§3.3.2): a node;
// an edge and its ends; or a face and its corners.
bool bindsOnePrimitive(const ir::Rule& r) {
    if (r.faces.size() == 1 && r.edges.empty()) {
        const auto& f = r.faces[0];
        for (std::size_t i = 0; i < r.nodes.size(); ++i)
            if (r.nodes[i].anchorOf != 0 && std::find(f.corners.begin(), f.corners.end(), static_cast<int>(i)) == f.corners.end())
                return false;
        return true;
    }
    if (r.faces.empty() && r.edges.size() == 1) return r.nodes.size() <= 2;
    return r.faces.empty() && r.edges.empty() && r.nodes.size() == 1;
}

}  // namespace

void checkSequence(Globals& g, const ast::SequenceDecl& d, const std::map<std::string, int>& ruleIndex) {
    if (!g.prog.sequence.empty()) {
        g.diags.error(d.span, "a grammar has one `sequence`, but this is a second one");
        return;
    }
    g.prog.sequence = entries(g, d, ruleIndex);
}

void checkCompoundMatch(Globals& g, ExprChecker& ec, const ast::CompoundDecl& d) {
    checkRule(g, ec, d.match);
    ir::Rule& r = g.prog.rules.back();
    r.compound = static_cast<int>(g.prog.compounds.size());
    if (!bindsOnePrimitive(r))
        g.diags.error(d.match.matchSpan, "a compound starts from one primitive: its match binds a node, an edge (with its ends) "
                                         "or a face (with its corners), and nothing else");
    ir::Compound c{r.name, static_cast<int>(g.prog.rules.size() - 1), {}, {}, d.span};
    for (const auto& l : r.lets) {
        const ir::TypeKind k = l.value.type.kind;
        if (k == ir::TypeKind::Int || k == ir::TypeKind::Float || k == ir::TypeKind::Bool || k == ir::TypeKind::Vec2 || k == ir::TypeKind::Vec3)
            c.lets.push_back(ir::Compound::Let{l.name, l.value.type});
        else
            g.diags.error(l.value.span, "a compound's `let` is a number, a truth value or a vector, not " + g.typeName(l.value.type));
    }
    if (auto it = g.compounds.find(c.name); it == g.compounds.end() || it->second < 0) g.compounds[c.name] = static_cast<int>(g.prog.compounds.size());
    g.prog.compounds.push_back(std::move(c));
}

void checkCompoundBodies(Globals& g, const std::vector<const ast::CompoundDecl*>& decls, const std::map<std::string, int>& ruleIndex) {
    for (std::size_t c = 0; c < decls.size(); ++c) g.prog.compounds[c].entries = entries(g, decls[c]->body, ruleIndex);
    // A compound within itself would never end.
    std::vector<int> state(decls.size(), 0);   // 0 unseen, 1 on the path, 2 done
    std::function<bool(int)> cycles = [&](int c) {
        if (state[static_cast<std::size_t>(c)] == 1) return true;
        if (state[static_cast<std::size_t>(c)] == 2) return false;
        state[static_cast<std::size_t>(c)] = 1;
        for (const auto& e : g.prog.compounds[static_cast<std::size_t>(c)].entries)
            if (e.compound && cycles(e.index)) return true;
        state[static_cast<std::size_t>(c)] = 2;
        return false;
    };
    for (std::size_t c = 0; c < decls.size(); ++c)
        if (state[c] == 0 && cycles(static_cast<int>(c))) {
            g.diags.error(decls[c]->match.name.span, "compound `" + decls[c]->match.name.name + "` contains itself (directly or "
                                                                                              "through another compound)");
            return;
        }
}

void checkCommandListsReach(Globals& g) {
    auto& prog = g.prog;
    if (prog.sequence.empty()) {
        for (const auto& c : prog.compounds)
            g.diags.error(c.span, "compound `" + c.name + "` runs only from a `sequence { … }`, and the grammar has none");
        for (const auto& r : prog.rules)
            if (r.intersect)
                g.diags.error(r.span, "rule `" + r.name + "` has `intersect`, which needs a `sequence { … }` (a command applies once; "
                                      "without one an undone application would be tried again and again)");
        return;
    }
    // What the sequence runs, directly or through compounds (`within`: the
    // compounds around); a rule reading `C.name` must run within C.
    std::vector<char> rules(prog.rules.size(), 0), compounds(prog.compounds.size(), 0);
    std::set<std::pair<int, int>> reported;
    auto readsWithin = [&](int rule, const std::vector<int>& within) {
        auto it = g.compoundReads.find(rule);
        if (it == g.compoundReads.end()) return;
        for (const auto& [c, span] : it->second)
            if (std::find(within.begin(), within.end(), c) == within.end() && reported.emplace(rule, c).second)
                g.diags.error(span, "`" + prog.rules[static_cast<std::size_t>(rule)].name + "` reads a value of compound `" +
                                        prog.compounds[static_cast<std::size_t>(c)].name + "` but also runs outside it");
    };
    std::vector<int> within;
    std::function<void(const std::vector<ir::SequenceEntry>&)> reach = [&](const std::vector<ir::SequenceEntry>& list) {
        for (const auto& e : list) {
            if (!e.compound) {
                rules[static_cast<std::size_t>(e.index)] = 1;
                readsWithin(e.index, within);
                continue;
            }
            compounds[static_cast<std::size_t>(e.index)] = 1;
            readsWithin(prog.compounds[static_cast<std::size_t>(e.index)].matchRule, within);
            within.push_back(e.index);
            reach(prog.compounds[static_cast<std::size_t>(e.index)].entries);
            within.pop_back();
        }
    };
    reach(prog.sequence);
    for (std::size_t c = 0; c < prog.compounds.size(); ++c)
        if (!compounds[c] && prog.compounds[c].span.file == g.mainFile)
            g.diags.warning(prog.compounds[c].span, "compound `" + prog.compounds[c].name + "` is in no `sequence`: it never runs");
    for (std::size_t r = 0; r < prog.rules.size(); ++r)
        if (!rules[r] && prog.rules[r].compound < 0 && prog.rules[r].span.file == g.mainFile)
            g.diags.warning(prog.rules[r].span, "rule `" + prog.rules[r].name + "` is in no `sequence` (nor compound): with a "
                                                "sequence, only the commands it lists apply");
    // A command list applies each command once, so a rule's limit never stops anything.
    for (const auto& r : prog.rules)
        if (r.limit && r.span.file == g.mainFile)
            g.diags.warning(r.limit->span, "rule `" + r.name + "` has a `limit`, which a `sequence` does not read: each command "
                                           "applies once where the list names it");
}

}  // namespace g2d::sema
