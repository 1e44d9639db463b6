#pragma once
// Every rule's matches, found once on the axiom and then repaired after each
// step around what the step changed: for each rule, the matches a change can
// have broken are dropped, and the matches binding a changed node (or one
// within `radius` edges of it) that the set lacks are found by anchored
// searches. A match reads only its own elements (a changed attribute marks
// its nodes), so the radius is 0 unless negative conditions look further; a
// rule whose negative condition is not connected to its match is searched in
// full. A node that changed itself (or lies in the radius) has every match
// binding it dropped and searched again. A node whose edges alone changed
// (one was added or removed) is revisited only at the pattern nodes that read
// incidences (RuleInfo::readsIncidence), and among those only at the ones
// reading the list that changed, outgoing or incoming
// (RuleInfo::readDirections): a resource whose token moves does not re-find
// every request pairing it with each process, and splitting a path's edge
// s->e revisits s alone. Where such a
// pattern node reads only the pattern's own edges, a match binding the node
// there is dropped only if it binds a removed edge, and only matches binding
// a new edge are searched from there (new edges have the highest ids, which
// are never reused): splitting one edge of a path leaves the next edge's
// match in place. An edge whose attributes or ends change marks its ends as
// changed themselves. Each missing match is added from exactly one anchor
// (RepairArea::bindsNewEdge says which), so no lookup is needed to avoid
// duplicates. A step thus costs what changed, not the size of the graph. Two
// exceptions: after a step that changed at least half of a graph's nodes (of
// 64 or more), every rule is searched in full, which is then cheaper; and a
// rule whose priority limit is used up is retired: its matches are no longer
// kept, so its conditions are no longer evaluated (nor can their run-time
// errors stop the derivation).
#include <cstdint>
#include <vector>

#include "g2d/derivation.hpp"
#include "g2d/grow_array.hpp"

namespace g2d::rt {

class IncrementalMatches {
public:
    static constexpr std::size_t kFullSearchMinNodes = 64;

    IncrementalMatches(RuleSet& rules, const Graph& g);
    ~IncrementalMatches();   // stops the rules' near queries (RuleSet::nearQueries)
    IncrementalMatches(const IncrementalMatches&) = delete;
    IncrementalMatches& operator=(const IncrementalMatches&) = delete;
    // After a step, before its changes are forgotten: brings the spatial
    // index of near conditions up to date (NearQueries::sync).
    void syncNear(const Graph& g) { rules_.nearQueries().sync(g); }

    MatchSet& of(std::size_t rule) { return sets_[rule]; }
    // Stops keeping `rule`'s matches (it will not be applied again): its set
    // is emptied and no longer repaired or verified.
    void retire(std::size_t rule);
    // Repairs every rule's set after the changes `g` recorded
    // (Graph::changedNodes; the caller forgets them after).
    // The step just applied added the edges from id `newEdgesFrom` on, and
    // the nodes from `newNodesFrom` on.
    // With `everything`, every rule is searched in full instead (and the
    // changes are not read: see searchesEverything).
    // Only the sets of rules reading a kind that the applied rule's daughter
    // `daughter` changes are repaired (RuleInfo::readKinds; kAnyDaughter: any
    // of its daughters, as after a parallel step).
    static constexpr std::size_t kAnyDaughter = ~std::size_t{0};
    // As `appliedRule`: several rules applied at once (a generation); every set is repaired.
    static constexpr std::size_t kAnyRule = ~std::size_t{0};
    void update(const Graph& g, EdgeId newEdgesFrom, NodeId newNodesFrom, bool everything, std::size_t appliedRule,
                std::size_t daughter);
    // How many sets of rules not retired updates have repaired or refilled,
    // and left alone as their step could not change them (--stats).
    std::size_t setsRepaired() const { return setsRepaired_; }
    std::size_t setsSkipped() const { return setsSkipped_; }
    // Whether the changes `g` has recorded are so many that the next update
    // should search every rule in full.
    static bool searchesEverything(const Graph& g);
    // Prefetches what the next update reads about the nodes of a match
    // about to be rewritten (their marks, their lists in the first rules'
    // sets), with the match's own records. Not in a graph of fewer than
    // kPrefetchMinNodes nodes: there they stay in the caches, and asking
    // for them only costs instructions (3-4 % of a small run's).
    void prefetch(const Graph& g, Match m, int nodes, int edges) const {
        if (g.nodeCapacity() >= kPrefetchMinNodes) prefetchMatch(g, m, nodes, edges);
    }
    static constexpr std::size_t kPrefetchMinNodes = 32768;
    // Throws std::logic_error unless every rule's set holds exactly the
    // matches a full search finds (the tests check this after every step).
    void verify(const Graph& g, long long step);
    std::size_t memoryBytes() const;

private:
    void prefetchMatch(const Graph& g, Match m, int nodes, int edges) const;
    // The changed nodes and those within `radius` edges of them, in area_,
    // marked in seen_ as RepairArea reads them.
    // With `values`, nodes whose attributes alone changed count as changed
    // themselves; without, only their edge lists' changes count.
    // areaSawValuesOnly_: whether such a node may be among the changes
    // (Graph::valuesWritten).
    void region(const Graph& g, int radius, bool values);
    bool areaSawValuesOnly_ = false;
    // Puts the changed nodes in area_ (those changed themselves, counting
    // attribute writes if kCountValues, first), marked `full` or `partial`.
    template <bool kCountValues>
    void collectChanged(const Graph& g, std::uint32_t full, std::uint32_t partial);
    bool inArea(NodeId n) const { return (seen_[n] >> 3) == mark_; }
    // Adds to the area, as changed themselves, the nodes whose near
    // conditions' disks a changed node lies in (NearQueries::touchedKeys).
    // Returns whether it added any (the area is then `rule`'s own).
    bool addTouchedKeys(std::size_t rule);
    // Empties `rule`'s set and fills it by a full search.
    void refill(std::size_t rule, const Graph& g);

    RuleSet& rules_;
    std::vector<MatchSet> sets_;
    std::vector<int> radius_;                // per rule (RuleInfo::radius)
    std::vector<std::vector<RepairAnchor>> anchors_;   // per rule, per pattern node
    std::vector<std::uint8_t> retired_;      // per rule (bytes: read per rule per step)
    // The rules by radius (stable).
    std::vector<std::size_t> byRadius_;
    // The rules whose sets a step applying `applied`'s daughter `daughter`
    // (kAnyDaughter or past the last: any) can change, by radius (so that
    // rules of one radius share one area), each marked with kReadsValues if
    // it reads an attribute the daughter writes (an area serves both kinds
    // of rule unless a node's attributes alone changed).
    void affectedBy(std::size_t applied, std::size_t daughter, std::vector<std::uint32_t>& out) const;
    static constexpr std::uint32_t kReadsValues = 0x80000000u;
    // affectedBy for a step, from the lists below or, without them, decided
    // now (in scratchAffected_).
    std::span<const std::uint32_t> affectedSets(std::size_t applied, std::size_t daughter);
    // affectedBy of every rule and daughter (and any daughter), listed once
    // where the grammar has at most kMaxListedPairs (rule, daughter, rule)
    // triples: a list of every triple grows with the square of the rules
    // (10^5 rules: 10^10 entries). The lists lie one after another in
    // listed_; list k ends at listEnds_[k]; rule r's lists are firstList_[r]
    // (daughter 0) to firstList_[r + 1] - 1 (any daughter). Empty beyond the
    // limit.
    static constexpr std::size_t kMaxListedPairs = std::size_t{1} << 20;
    std::vector<std::uint32_t> listed_, listEnds_, firstList_;
    std::vector<std::uint32_t> scratchAffected_;
    std::vector<std::uint32_t> allRules_;   // every rule by radius, reading values: after kAnyRule
    std::size_t setsRepaired_ = 0, setsSkipped_ = 0;
    std::size_t liveRules_ = 0;   // rules not retired
    GrowArray<std::uint32_t> seen_;
    std::uint32_t mark_ = 0;
    std::vector<NodeId> area_;
    std::vector<NodeId> touched_;
    MatchBuffer found_;
};

}  // namespace g2d::rt
