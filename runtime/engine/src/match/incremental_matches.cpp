#include "g2d/incremental_matches.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "g2d/prefetch.hpp"

namespace g2d::rt {

namespace {

template <class T>
bool shareAny(const std::vector<T>& a, const std::vector<T>& b) {
    for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
        if (*i == *j) return true;
        if (*i < *j) ++i;
        else ++j;
    }
    return false;
}

struct Effect {
    bool changes = false;   // the step can change `reader`'s matches
    bool values = false;    // through attributes `reader` reads, too
};

// What applying `applied`'s daughter `d` can do to the matches of `reader`.
Effect effectOf(const RuleInfo& applied, std::size_t d, const RuleInfo& reader) {
    if (!applied.kindsKnown || !reader.kindsKnown || d >= applied.changedKinds.size() ||
        d >= applied.changedValues.size() || d >= applied.deletesNodes.size())
        return {true, true};
    const bool values = shareAny(applied.changedValues[d], reader.readValues);
    return {values || shareAny(applied.changedKinds[d], reader.readKinds) || (reader.readsDegrees && applied.deletesNodes[d]),
            values};
}

}  // namespace

IncrementalMatches::IncrementalMatches(RuleSet& rules, const Graph& g) : rules_(rules) {
    std::vector<std::vector<int>> nearKinds;
    std::vector<int> joinKinds;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        const RuleInfo& info = rules.info(r);
        nearKinds.push_back(info.globalMatches ? info.nearKinds : std::vector<int>{});
        if (info.globalMatches) joinKinds.insert(joinKinds.end(), info.joinKinds.begin(), info.joinKinds.end());
    }
    rules.nearQueries().start(g, nearKinds, joinKinds);
    std::size_t pairs = 0;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        const RuleInfo& info = rules.info(r);
        const int nn = static_cast<int>(info.nodeKinds.size());
        sets_.emplace_back(nn, info.edgeCount, info.faceCount, info.pick, info.readsIncidence, info.readDirections);
        radius_.push_back(info.radius);
        anchors_.push_back(repairAnchors(info));
        byRadius_.push_back(r);
        retired_.push_back(info.globalMatches ? 0 : 1);   // searched within compounds' scopes only
        if (!info.globalMatches) continue;
        refill(r, g);
        ++liveRules_;
        pairs += (info.weights.size() + 1) * rules.ruleCount();
    }
    std::stable_sort(byRadius_.begin(), byRadius_.end(), [&](std::size_t a, std::size_t b) { return radius_[a] < radius_[b]; });
    for (const std::size_t r : byRadius_) allRules_.push_back(static_cast<std::uint32_t>(r) | kReadsValues);
    if (pairs > kMaxListedPairs) return;   // decided at each step instead (affectedBy)
    std::vector<std::uint32_t> list;
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        firstList_.push_back(static_cast<std::uint32_t>(listEnds_.size()));
        for (std::size_t d = 0; d <= rules.info(r).weights.size(); ++d) {
            affectedBy(r, d, list);
            listed_.insert(listed_.end(), list.begin(), list.end());
            listEnds_.push_back(static_cast<std::uint32_t>(listed_.size()));
        }
    }
    firstList_.push_back(static_cast<std::uint32_t>(listEnds_.size()));
}

IncrementalMatches::~IncrementalMatches() { rules_.nearQueries().stop(); }

void IncrementalMatches::affectedBy(std::size_t applied, std::size_t daughter, std::vector<std::uint32_t>& out) const {
    const RuleInfo& info = rules_.info(applied);
    out.clear();
    for (const std::size_t q : byRadius_) {
        Effect any;
        for (std::size_t d = 0; d < info.weights.size(); ++d) {
            if (daughter != d && daughter < info.weights.size()) continue;
            const Effect e = effectOf(info, d, rules_.info(q));
            any.changes = any.changes || e.changes;
            any.values = any.values || e.values;
        }
        if (any.changes) out.push_back(static_cast<std::uint32_t>(q) | (any.values ? kReadsValues : 0));
    }
}

template <bool kCountValues>
void IncrementalMatches::collectChanged(const Graph& g, std::uint32_t full, std::uint32_t partial) {
    const std::span<const NodeId> changed = g.changedNodes();
    for (NodeId n : changed)
        if (g.changedItself(n, kCountValues)) {
            seen_[n] = full;
            area_.push_back(n);
        }
    // Counting attribute writes, every other changed node had an edge list change.
    for (NodeId n : changed)
        if (!g.changedItself(n, kCountValues) && (kCountValues || g.changedLists(n) != 0)) {
            seen_[n] = partial + 2u * g.changedLists(n);
            area_.push_back(n);
        }
}

void IncrementalMatches::region(const Graph& g, int radius, bool values) {
    if (seen_.size() < g.nodeCapacity()) seen_.resize(g.nodeCapacity() + g.nodeCapacity() / 2, 0);
    if (++mark_ >= 0x1fffffffu) {  // about to wrap: forget every old mark
        std::fill(seen_.begin(), seen_.end(), 0);
        mark_ = 1;
    }
    const std::uint32_t full = mark_ * 8 + 1, partial = mark_ * 8;
    area_.clear();
    // The nodes that changed themselves first, then those whose edges alone
    // did, each in the order they changed. A node whose attributes alone
    // were written counts as changed itself only for rules reading such an
    // attribute (`values`); for the others, only its edge lists' changes do.
    // (Where no attributes were written, both views are the same.)
    areaSawValuesOnly_ = g.valuesWritten();
    if (values || !areaSawValuesOnly_) collectChanged<true>(g, full, partial);
    else collectChanged<false>(g, full, partial);
    // Nodes reached within the radius are revisited fully (a negative
    // condition's nodes may be there).
    auto reach = [&](NodeId o) {
        if (!inArea(o)) area_.push_back(o);
        seen_[o] = full;
    };
    std::size_t begin = 0;
    for (int d = 0; d < radius; ++d) {
        const std::size_t end = area_.size();
        for (std::size_t i = begin; i < end; ++i) {
            const NodeId n = area_[i];
            if (!g.nodeAlive(n)) continue;
            for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e)) reach(g.target(e));
            for (EdgeId e = g.firstIn(n); e != kNoId; e = g.nextIn(e)) reach(g.source(e));
            // A face joins its corners (lower::repairRadius counts them as near).
            for (CornerId c = g.firstCornerAt(n); c != kNoId; c = g.nextCornerAt(c))
                for (CornerId k = g.nextCorner(c); k != c; k = g.nextCorner(k)) reach(g.cornerNode(k));
        }
        begin = end;
    }
}

bool IncrementalMatches::searchesEverything(const Graph& g) {
    // When the step changed at least half of the nodes (a parallel step
    // rewriting a whole generation), one full search is cheaper than an
    // anchored search from every changed node at every pattern node, which
    // finds each match once per anchor. Small graphs keep to repair (its
    // cost is small there), so the tests' small random grammars compare the
    // back ends' repairs.
    return g.nodeCount() >= kFullSearchMinNodes && 2 * g.changedNodeCount() >= g.nodeCount();
}

std::span<const std::uint32_t> IncrementalMatches::affectedSets(std::size_t applied, std::size_t daughter) {
    if (applied == kAnyRule) return allRules_;
    if (firstList_.empty()) {
        affectedBy(applied, daughter, scratchAffected_);
        return scratchAffected_;
    }
    const std::uint32_t first = firstList_[applied], last = firstList_[applied + 1] - 1;   // last: any daughter
    const std::uint32_t list = daughter < last - first ? first + static_cast<std::uint32_t>(daughter) : last;
    const std::uint32_t begin = list == 0 ? 0 : listEnds_[list - 1];
    return {listed_.data() + begin, listEnds_[list] - begin};
}

void IncrementalMatches::update(const Graph& g, EdgeId newEdgesFrom, NodeId newNodesFrom, bool everything,
                                std::size_t appliedRule, std::size_t daughter) {
    if (!everything && g.changedNodes().empty()) return;
    const std::span<const std::uint32_t> affected = affectedSets(appliedRule, daughter);
    int areaRadius = -1;   // the radius area_ was built for in this call (none yet)
    bool areaValues = false;
    std::size_t repaired = 0;
    for (const std::uint32_t entry : affected) {
        const std::uint32_t r = entry & ~kReadsValues;
        const bool values = (entry & kReadsValues) != 0;
        if (retired_[r]) continue;
        ++repaired;
        MatchSet& set = sets_[r];
        if (radius_[r] < 0 || everything) {
            // Not local, or not worth it: find them all again.
            refill(r, g);
            continue;
        }
        // (An area serves both views where no node's attributes alone changed.)
        if (radius_[r] != areaRadius || (values != areaValues && areaSawValuesOnly_)) {
            region(g, radius_[r], values);
            areaRadius = radius_[r];
            areaValues = values;
        }
        if (!rules_.info(r).nearKinds.empty() && addTouchedKeys(r)) areaRadius = -2;   // not for the next rule
        const RepairArea area{area_, seen_.data(), mark_, newEdgesFrom, newNodesFrom};
        for (NodeId n : area_) {
            if (area.full(n)) {
                set.removeTouching(n);
                if (!rules_.info(r).nearKinds.empty()) rules_.nearQueries().forget(r, n);
            } else {
                set.removeBrokenAt(n, area.edgeChanges(n), g);
            }
        }
        rules_.repair(r, g, area, anchors_[r].data(), set, found_);
    }
    setsRepaired_ += repaired;
    setsSkipped_ += liveRules_ - repaired;
}

void IncrementalMatches::prefetchMatch(const Graph& g, Match m, int nodes, int edges) const {
    for (int i = 0; i < nodes; ++i) {
        const NodeId n = m.nodes[i];
        g.prefetchNode(n);
        if (n < seen_.size()) prefetchLine(&seen_[n]);
        for (std::size_t r = 0; r < sets_.size() && r < 4; ++r)
            if (!retired_[r]) sets_[r].prefetchHeads(n);
    }
    for (int i = 0; i < edges; ++i) g.prefetchEdge(m.edges[i]);
}

bool IncrementalMatches::addTouchedKeys(std::size_t rule) {
    touched_.clear();
    rules_.nearQueries().touchedKeys(rule, touched_);
    const std::uint32_t full = mark_ * 8 + 1;
    bool added = false;
    for (NodeId n : touched_) {
        if (inArea(n) && seen_[n] == full) continue;
        if (!inArea(n)) area_.push_back(n);
        seen_[n] = full;
        added = true;
    }
    return added;
}

void IncrementalMatches::refill(std::size_t rule, const Graph& g) {
    MatchSet& set = sets_[rule];
    set.clear();
    rules_.nearQueries().forgetRule(rule);
    found_.reset(set.nodes(), set.edges(), set.faces());
    rules_.findMatches(rule, g, found_);
    for (std::size_t i = 0; i < found_.size(); ++i) set.add(found_.ids(i), g);
}

void RuleSet::repair(std::size_t rule, const Graph& g, const RepairArea& area, const RepairAnchor* anchors, MatchSet& set,
                     MatchBuffer& scratch) {
    const int nn = set.nodes();
    for (NodeId h : area.nodes) {
        if (!g.nodeAlive(h)) continue;
        const bool full = area.full(h);
        const int hostKind = g.nodeKind(h);
        for (int p = 0; p < nn; ++p) {
            if (!area.searchesAt(h, full, hostKind, anchors[p])) continue;
            scratch.reset(nn, set.edges(), set.faces());
            findAnchored(rule, g, p, h, scratch, area.newEdgesOnly(full, anchors[p]));
            for (std::size_t i = 0; i < scratch.size(); ++i) {
                const std::uint32_t* ids = scratch.ids(i);
                if (area.firstAnchor(p, ids, ids + nn, set.edges(), anchors)) set.add(ids, g);
            }
        }
    }
}

void IncrementalMatches::retire(std::size_t rule) {
    if (retired_[rule]) return;
    retired_[rule] = 1;
    --liveRules_;
    sets_[rule].release();
}

void IncrementalMatches::verify(const Graph& g, long long step) {
    using Key = std::vector<std::uint32_t>;
    for (std::size_t r = 0; r < sets_.size(); ++r) {
        if (retired_[r]) continue;
        const MatchSet& set = sets_[r];
        const std::size_t width = static_cast<std::size_t>(set.nodes() + set.edges() + set.faces());
        found_.reset(set.nodes(), set.edges(), set.faces());
        rules_.nearQueries().forgetRule(r);   // recorded afresh by the search
        rules_.findMatches(r, g, found_);
        std::vector<Key> all, kept;
        for (std::size_t i = 0; i < found_.size(); ++i) all.emplace_back(found_.ids(i), found_.ids(i) + width);
        for (std::size_t i = 0; i < set.size(); ++i) kept.emplace_back(set.idsAt(i), set.idsAt(i) + width);
        std::sort(all.begin(), all.end());
        std::sort(kept.begin(), kept.end());
        if (all != kept)
            throw std::logic_error("incremental matching lost track of rule " + std::to_string(r) + " after step " +
                                   std::to_string(step) + ": " + std::to_string(kept.size()) + " matches kept, " +
                                   std::to_string(all.size()) + " found");
    }
}

std::size_t IncrementalMatches::memoryBytes() const {
    std::size_t bytes = seen_.capacity() * 4 + area_.capacity() * 4;
    for (const auto& s : sets_) bytes += s.memoryBytes();
    return bytes;
}

}  // namespace g2d::rt
