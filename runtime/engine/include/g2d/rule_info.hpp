#pragma once
// What the scheduler and incremental matching know of a rule (RuleInfo),
// and the list of its fields, for code that prints one as data (the C++
// emitter).
#include <cstdint>
#include <string>
#include <vector>

#include "g2d/angle_step.hpp"
#include "g2d/match_set.hpp"
#include "g2d/pick.hpp"

namespace g2d::rt {

struct RuleInfo {
    std::string name;                 // as written in the grammar (traces, messages)
    long long priority = 0;
    Pick pick = Pick::Random;
    bool parallel = false;
    // Its priority is a generation (`priority P generation;`): when the
    // priority's turn comes, every one of its rules rewrites all its matches
    // in one step (ParallelStep::runGeneration).
    bool generation = false;
    std::vector<double> weights;      // one per daughter, all > 0 (0 for those read from the match)
    // `weight W` of the rule (> 0): a priority whose rules' weights are not
    // all 1 chooses among its matching rules by weight (one Rng::unit draw)
    // instead of trying them in a random order.
    double choiceWeight = 1;
    // Some daughter's weight reads the match: RuleSet::weigh gives them per application.
    bool matchWeighted = false;
    // The pattern's shape, for incremental matching: the kinds of its nodes
    // (-1: wildcard), its edge count, and how far (in edges) from a changed
    // node a match can be affected through its negative conditions (-1:
    // anywhere, so every change means a full search for this rule).
    std::vector<int> nodeKinds;
    int edgeCount = 0;
    int faceCount = 0;
    int radius = 0;
    // Per pattern node: which edge changes alone at its host matter (see
    // IncrementalMatches); empty means all do.
    std::vector<Incidence> readsIncidence;
    // Per pattern node: which of the host's edge lists it reads
    // (RepairArea::kOut | kIn; lower::incidenceDirections); empty: both
    // wherever readsIncidence reads any.
    std::vector<std::uint8_t> readDirections;
    // Per pattern node: whether a search anchored there at a node the step
    // created can add nothing (lower::newHostsAddingNothing); empty: none.
    std::vector<std::uint8_t> newHostAddsNothing;
    // Which kinds of element this rule's matches read, and which each of its
    // daughters changes (lower::KindEffects;
    // node and edge kinds share one numbering): after a step whose daughter
    // changes no kind a rule reads, that rule's matches are as they were,
    // and its set is not repaired (IncrementalMatches). Without
    // `kindsKnown` (a hand-built RuleSet), every step repairs every set.
    // Likewise node attributes (as lower::valueKey): for a rule reading none of the
    // attributes a daughter writes, a node whose only change is such a write
    // (Graph::touchNodeValues) is not revisited.
    bool kindsKnown = false;
    std::vector<int> readKinds;                     // sorted
    bool readsDegrees = false;                      // so removing any edge at a match node matters
    // Whether a condition reads a face's `neighbours`: only then does adding
    // or removing a face mark its neighbours' anchors (Graph::trackNeighbours).
    bool readsNeighbours = true;
    std::vector<long long> readValues;              // sorted
    std::vector<std::vector<int>> changedKinds;     // per daughter, sorted
    std::vector<std::vector<long long>> changedValues;   // per daughter, sorted
    std::vector<std::uint8_t> deletesNodes;         // per daughter: removes a node (and so its edges)
    // G^3's merging (node_merge.hpp): after each step of this rule, new and
    // moved nodes within this distance of another node merge with it
    // (0: no merging).
    double mergeTolerance = 0;
    // Whether its matches are kept over the whole graph (IncrementalMatches):
    // with a command list, only those of the rules and compounds the list
    // names itself; the others run within compounds' scopes (compound_run.hpp).
    bool globalMatches = true;
    // G^3's intersection tests (intersection_guard.hpp): an application
    // whose additions would intersect the model is undone.
    bool intersect = false;
    // ... with the plane's tests (a 2D grammar): a face is an area, crossed
    // by crossing its outline (intersection_guard.hpp).
    bool intersectInPlane = false;
    // Per negative condition asking for a node near a point
    // (lower::nearNegative), in order: that node's kind. Their searches go
    // through RuleSet::nearQueries(), and repair revisits the matches whose
    // disks a changed node of the kind lies in.
    std::vector<int> nearKinds;
    // The kinds of pattern nodes a search may find near bound ones
    // (lower::nearJoin; -1: any node): NearQueries indexes them.
    std::vector<int> joinKinds;
    // With `layout angles` (RuleSet::angleLayout): per daughter, what it
    // does to the graph, for the drawing step (angle_step.hpp).
    std::vector<DaughterShape> shapes;
};

// Calls visit(name, field) for every field of RuleInfo, in declaration order.
// rule_info_test counts the struct's fields against this list, so a field
// added there and not here fails the suite instead of being left out of
// generated programs.
template <class Info, class Visit>
void eachRuleInfoField(Info& i, Visit&& visit) {
    visit("name", i.name);
    visit("priority", i.priority);
    visit("pick", i.pick);
    visit("parallel", i.parallel);
    visit("generation", i.generation);
    visit("weights", i.weights);
    visit("choiceWeight", i.choiceWeight);
    visit("matchWeighted", i.matchWeighted);
    visit("nodeKinds", i.nodeKinds);
    visit("edgeCount", i.edgeCount);
    visit("faceCount", i.faceCount);
    visit("radius", i.radius);
    visit("readsIncidence", i.readsIncidence);
    visit("readDirections", i.readDirections);
    visit("newHostAddsNothing", i.newHostAddsNothing);
    visit("kindsKnown", i.kindsKnown);
    visit("readKinds", i.readKinds);
    visit("readsDegrees", i.readsDegrees);
    visit("readsNeighbours", i.readsNeighbours);
    visit("readValues", i.readValues);
    visit("changedKinds", i.changedKinds);
    visit("changedValues", i.changedValues);
    visit("deletesNodes", i.deletesNodes);
    visit("mergeTolerance", i.mergeTolerance);
    visit("globalMatches", i.globalMatches);
    visit("intersect", i.intersect);
    visit("intersectInPlane", i.intersectInPlane);
    visit("nearKinds", i.nearKinds);
    visit("joinKinds", i.joinKinds);
    visit("shapes", i.shapes);
}

}  // namespace g2d::rt
