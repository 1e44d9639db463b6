#include "sema/sequence_checker.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "sema/const_fold.hpp"
#include "sema/decl_checker.hpp"
#include "sema/graph_checker.hpp"
#include "diag/suggest.hpp"

namespace g2d::sema {

namespace {

// A list written out past this many entries is a mistake (a repeat says it shorter).
constexpr std::size_t kMaxListEntries = 1'000'000;

}  // namespace

CommandLists::CommandLists(Globals& g, ExprChecker& ec, const std::map<std::string, int>& rules, std::vector<const ast::SequenceDecl*> named)
    : g_(g), ec_(ec), rules_(rules) {
    for (const auto* d : named) named_.emplace(d->name->name, d);   // a second of one name is reported as a name clash
    for (const auto* d : named) list(*d, *d->name);                 // checked even when nothing names it
}

std::vector<ir::SequenceEntry> CommandLists::entries(const ast::SequenceDecl& d) {
    std::vector<ir::SequenceEntry> out;
    if (d.items.empty()) g_.diags.error(d.span, "an empty `sequence` would apply nothing; list rules, each followed by `;`");
    expand(d.items, out);
    return out;
}

const std::vector<ir::SequenceEntry>& CommandLists::list(const ast::SequenceDecl& d, const ast::Ident& at) {
    static const std::vector<ir::SequenceEntry> none;
    const std::string& name = d.name->name;
    if (auto it = done_.find(name); it != done_.end()) return it->second;
    if (std::find(open_.begin(), open_.end(), name) != open_.end()) {
        if (!cycles_.insert(name).second) return none;   // said once
        std::string path;
        for (auto it = std::find(open_.begin(), open_.end(), name) + 1; it != open_.end(); ++it) path += (path.empty() ? "" : ", ") + ("`" + *it + "`");
        g_.diags.error(at.span, "sequence `" + name + "` contains itself" + (path.empty() ? "" : " (through " + path + ")") +
                                    ": it would never end; a `repeat N { … }` runs entries again");
        return none;
    }
    open_.push_back(name);
    std::vector<ir::SequenceEntry> out = entries(d);
    open_.pop_back();
    return done_[name] = std::move(out);
}

void CommandLists::expand(const std::vector<ast::SequenceItem>& items, std::vector<ir::SequenceEntry>& out) {
    for (const auto& item : items) {
        if (item.count) {
            repeat(item, out);
        } else if (auto r = rules_.find(item.name.name); r != rules_.end()) {
            const int compound = g_.prog.rules[static_cast<std::size_t>(r->second)].compound;
            out.push_back(compound >= 0 ? ir::SequenceEntry{ir::SequenceEntry::Kind::Compound, compound, 0}
                                        : ir::SequenceEntry{ir::SequenceEntry::Kind::Rule, r->second, 0});
        } else if (auto l = named_.find(item.name.name); l != named_.end()) {
            used_.insert(item.name.name);
            const auto& entries = list(*l->second, item.name);
            out.insert(out.end(), entries.begin(), entries.end());
        } else {
            std::vector<std::string> names;
            for (const auto& [name, index] : rules_) names.push_back(name);
            for (const auto& [name, decl] : named_) names.push_back(name);
            g_.diags.error(item.name.span, "no rule, compound or sequence named `" + item.name.name + "`" + suggest(item.name.name, names));
        }
        if (out.size() > kMaxListEntries && !tooLong_) {
            tooLong_ = true;
            g_.diags.error(item.span, "this command list grows past " + std::to_string(kMaxListEntries) +
                                          " entries when its named lists are written out; say it with `repeat N { … }`");
        }
        if (tooLong_) return;
    }
}

// `repeat N { … }`: a header, then its entries; N is checked once, however
// often a named list around it is written out.
void CommandLists::repeat(const ast::SequenceItem& item, std::vector<ir::SequenceEntry>& out) {
    auto [it, first] = counts_.emplace(&item, -1);
    if (first) {
        if (auto count = checkCount(g_, ec_, *item.count, "a repeat count")) {
            if (const auto n = fold(*count, g_.prog); n && std::get<long long>(*n) == 0)
                g_.diags.warning(item.count->span, "`repeat 0` never runs its entries");
            it->second = static_cast<int>(g_.prog.repeatCounts.size());
            g_.prog.repeatCounts.push_back(std::move(*count));
        }
        if (item.body.empty()) g_.diags.error(item.span, "an empty `repeat` would apply nothing; list rules in it, each followed by `;`");
    }
    const std::size_t at = out.size();
    out.push_back(ir::SequenceEntry{ir::SequenceEntry::Kind::Repeat, it->second, 0});
    expand(item.body, out);
    out[at].body = static_cast<int>(out.size() - at - 1);
}

void CommandLists::warnUnused() const {
    for (const auto& [name, d] : named_)
        if (!used_.count(name) && d->span.file == g_.mainFile)
            g_.diags.warning(d->name->span, "sequence `" + name + "` is named by no list: it never runs");
}

namespace {

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

void checkSequence(Globals& g, const ast::SequenceDecl& d, CommandLists& lists) {
    if (!g.prog.sequence.empty()) {
        g.diags.error(d.span, "a grammar has one `sequence`, but this is a second one");
        return;
    }
    g.prog.sequence = lists.entries(d);
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

void checkCompoundBodies(Globals& g, const std::vector<const ast::CompoundDecl*>& decls, CommandLists& lists) {
    for (std::size_t c = 0; c < decls.size(); ++c) g.prog.compounds[c].entries = lists.entries(decls[c]->body);
    // A compound within itself would never end.
    std::vector<int> state(decls.size(), 0);   // 0 unseen, 1 on the path, 2 done
    std::function<bool(int)> cycles = [&](int c) {
        if (state[static_cast<std::size_t>(c)] == 1) return true;
        if (state[static_cast<std::size_t>(c)] == 2) return false;
        state[static_cast<std::size_t>(c)] = 1;
        for (const auto& e : g.prog.compounds[static_cast<std::size_t>(c)].entries)
            if (e.kind == ir::SequenceEntry::Kind::Compound && cycles(e.index)) return true;
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
            if (e.kind == ir::SequenceEntry::Kind::Repeat) continue;   // its entries follow it
            if (e.kind == ir::SequenceEntry::Kind::Rule) {
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
