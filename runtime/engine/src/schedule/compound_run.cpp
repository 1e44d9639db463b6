#include "g2d/compound_run.hpp"

#include "g2d/applied_hook.hpp"

#include <array>

namespace g2d::rt {

namespace {

MatchSet emptySet(const RuleInfo& info) {
    return MatchSet(static_cast<int>(info.nodeKinds.size()), info.edgeCount, info.faceCount, info.pick);
}

bool inScope(const ElementScope& s, Match m, int nodes, int edges, int faces) {
    for (int i = 0; i < nodes; ++i)
        if (!s.has(ElemClass::Node, m.nodes[i])) return false;
    for (int i = 0; i < edges; ++i)
        if (!s.has(ElemClass::Edge, m.edges[i])) return false;
    for (int i = 0; i < faces; ++i)
        if (!s.has(ElemClass::Face, m.faces[i])) return false;
    return true;
}

}  // namespace

bool CompoundRun::run(std::size_t c, const MatchSet& initial, long long& applications) {
    std::vector<std::size_t> instances;
    for (std::size_t i = 0; i < initial.size(); ++i)
        instances.push_back(newInstance(c, initial.at(i), initial.nodes(), initial.edges(), initial.faces(), {}));
    if (instances.empty()) hooks_.foundNone();
    return runEntries(c, instances, applications);
}

std::size_t CompoundRun::newInstance(std::size_t c, Match m, int nodes, int edges, int faces, std::vector<std::size_t> parents) {
    Instance& in = instances_.emplace_back();
    for (int i = 0; i < nodes; ++i) in.scope.addWithParts(g_, ElemClass::Node, m.nodes[i]);
    for (int i = 0; i < edges; ++i) in.scope.addWithParts(g_, ElemClass::Edge, m.edges[i]);
    for (int i = 0; i < faces; ++i) in.scope.addWithParts(g_, ElemClass::Face, m.faces[i]);
    in.parents = std::move(parents);
    in.scope.compound = static_cast<int>(c);
    if (!in.parents.empty()) in.scope.parent = &instances_[in.parents.front()].scope;
    g_.setScope(&in.scope);
    try {
        in.scope.values = rules_.compoundValues(c, m, g_, rng_);
    } catch (...) {
        g_.setScope(nullptr);
        throw;
    }
    g_.setScope(nullptr);
    return instances_.size() - 1;
}

void CompoundRun::scopedMatches(std::size_t rule, const std::vector<std::size_t>& instances, MatchSet& set,
                                std::vector<std::vector<std::size_t>>& owners) {
    const int nn = set.nodes(), ne = set.edges(), nf = set.faces();
    const std::size_t width = static_cast<std::size_t>(nn + ne + nf);
    std::map<std::vector<std::uint32_t>, std::size_t> index;   // a match's ids -> its place in the set
    for (std::size_t in : instances) {
        const ElementScope& scope = instances_[in].scope;
        buffer_.reset(nn, ne, nf);
        g_.setScope(&scope);
        try {
            // Every node of a match in the scope is the scope's, its first
            // one too: the search starts there, not from the whole graph.
            if (nn == 0) {
                rules_.findMatches(rule, g_, buffer_);
            } else {
                const int kind = rules_.info(rule).nodeKinds[0];
                for (NodeId h : scope.nodes())
                    if (g_.nodeAlive(h) && (kind < 0 || g_.nodeKind(h) == kind)) rules_.findAnchored(rule, g_, 0, h, buffer_);
            }
        } catch (...) {
            g_.setScope(nullptr);
            throw;
        }
        g_.setScope(nullptr);
        for (std::size_t i = 0; i < buffer_.size(); ++i) {
            if (!inScope(scope, buffer_[i], nn, ne, nf)) continue;
            std::vector<std::uint32_t> key(buffer_.ids(i), buffer_.ids(i) + width);
            auto [at, added] = index.emplace(std::move(key), set.size());
            if (added) {
                set.add(buffer_.ids(i), g_);
                owners.emplace_back();
            }
            owners[at->second].push_back(in);
        }
    }
}

void CompoundRun::addToScopes(std::size_t instance, ElemClass c, std::uint32_t from, std::uint32_t to) {
    Instance& in = instances_[instance];
    for (std::uint32_t id = from; id < to; ++id) in.scope.add(c, id);
    for (std::size_t parent : in.parents) addToScopes(parent, c, from, to);
}

bool CompoundRun::runEntries(std::size_t c, const std::vector<std::size_t>& instances, long long& applications) {
    const std::vector<SequenceEntry> entries = rules_.compounds()[c].entries;
    return forEachCommand(entries, counts_, [&](const SequenceEntry& e) {
        if (e.kind == SequenceEntry::Compound) {
            const std::size_t matchRule = rules_.compounds()[e.index].matchRule;
            MatchSet found = emptySet(rules_.info(matchRule));
            std::vector<std::vector<std::size_t>> owners;
            scopedMatches(matchRule, instances, found, owners);
            std::vector<std::size_t> children;
            for (std::size_t i = 0; i < found.size(); ++i)
                children.push_back(newInstance(e.index, found.at(i), found.nodes(), found.edges(), found.faces(), owners[i]));
            if (children.empty()) hooks_.foundNone();
            return runEntries(e.index, children, applications);
        }
        if (!hooks_.mayStep()) return false;
        const long long step = hooks_.nextStep();
        const auto newEdgesFrom = static_cast<EdgeId>(g_.edgeCapacity());
        const auto newNodesFrom = static_cast<NodeId>(g_.nodeCapacity());
        MatchSet set = emptySet(rules_.info(e.index));
        std::vector<std::vector<std::size_t>> owners;
        scopedMatches(e.index, instances, set, owners);
        if (!set.empty()) {
            // Ids are never reused: an application created the ids from the
            // graph's capacities before it up to those after it.
            using Capacities = std::array<std::size_t, 3>;
            auto capacities = [&] { return Capacities{g_.nodeCapacity(), g_.edgeCapacity(), g_.faceCapacity()}; };
            std::vector<const ElementScope*> scopes;
            for (const auto& o : owners) scopes.push_back(&instances_[o.front()].scope);
            std::vector<Capacities> after;
            Capacities from = capacities();
            {
                AppliedHook hook(rules_, [&] { after.push_back(capacities()); });
                applications += static_cast<long long>(hooks_.apply(e.index, set, step, scopes.data()));
            }
            std::size_t j = 0;
            for (std::size_t i = 0; i < set.size() && j < after.size(); ++i) {
                if (!parallel_.taken(i)) continue;
                const Capacities& to = after[j++];
                for (std::size_t owner : owners[i]) {
                    addToScopes(owner, ElemClass::Node, static_cast<std::uint32_t>(from[0]), static_cast<std::uint32_t>(to[0]));
                    addToScopes(owner, ElemClass::Edge, static_cast<std::uint32_t>(from[1]), static_cast<std::uint32_t>(to[1]));
                    addToScopes(owner, ElemClass::Face, static_cast<std::uint32_t>(from[2]), static_cast<std::uint32_t>(to[2]));
                }
                from = to;
            }
            hooks_.afterStep(e.index, step, newEdgesFrom, newNodesFrom);
        }
        hooks_.stepDone(step);
        return true;
    });
}

}  // namespace g2d::rt
