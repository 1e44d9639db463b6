#include "lower/rule_facts.hpp"

#include <algorithm>

#include "lower/kind_effects.hpp"
#include "lower/near_negative.hpp"
#include "lower/search_plan.hpp"
#include "g2d/node_merge.hpp"

namespace g2d::lower {

RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& r, const std::vector<RewriteProgram>& daughters) {
    RuleFacts out;
    rt::RuleInfo& info = out.info;
    info.name = r.name;
    info.priority = r.priority;
    info.pick = r.pick;
    info.parallel = ir::runsParallel(prog, r);
    info.generation = ir::inGeneration(prog, r);
    using Field = SetRuleNumber::Field;
    for (std::size_t d = 0; d < r.daughters.size(); ++d) {
        const ir::Daughter& dg = r.daughters[d];
        info.weights.push_back(dg.weight ? *dg.weight : dg.weightExpr ? 0.0 : 1.0);
        info.matchWeighted = info.matchWeighted || dg.weightReadsMatch;
        if (dg.weight || !dg.weightExpr) continue;
        if (dg.weightReadsMatch) out.matchWeights.weights.push_back({static_cast<int>(d), &*dg.weightExpr});
        else out.startNumbers.push_back({Field::DaughterWeight, static_cast<int>(d), &*dg.weightExpr, kWeightCheck});
    }
    const bool choiceByParameter = r.weightExpr && r.weightExpr->op != ir::ExprOp::Literal;
    info.choiceWeight = choiceByParameter ? 0.0 : r.weight;
    if (choiceByParameter) out.startNumbers.push_back({Field::ChoiceWeight, -1, &*r.weightExpr, kWeightCheck});
    info.radius = repairRadius(r);
    for (std::size_t k = 0; k < r.nacs.size(); ++k)
        if (const auto near = nearNegative(r, k)) info.nearKinds.push_back(near->kind);
    if (!r.ordered)
        for (std::size_t i = 0; i < r.nodes.size(); ++i) {
            const int node = static_cast<int>(i);
            const auto join = nearJoin(r.conditions, r.nodes[i], node, [&](int n) { return n != node; });
            if (join && std::find(info.joinKinds.begin(), info.joinKinds.end(), join->kind) == info.joinKinds.end())
                info.joinKinds.push_back(join->kind);
        }
    info.readsIncidence = incidenceReaders(r);
    std::vector<bool> directed;
    for (const auto& k : prog.kinds) directed.push_back(k.directed);
    info.readDirections = incidenceDirections(r, directed, info.readsIncidence);
    for (bool nothing : newHostsAddingNothing(r, info.readsIncidence)) info.newHostAddsNothing.push_back(nothing ? 1 : 0);
    for (const auto& n : r.nodes) info.nodeKinds.push_back(n.kind);
    info.edgeCount = static_cast<int>(r.edges.size());
    info.faceCount = static_cast<int>(r.faces.size());
    info.kindsKnown = true;
    if (!prog.sequence.empty()) {
        // `r` is one of prog.rules: its index, as the sequence names it.
        const int index = static_cast<int>(std::find_if(prog.rules.begin(), prog.rules.end(), [&](const ir::Rule& x) { return &x == &r; }) -
                                           prog.rules.begin());
        info.globalMatches = false;
        for (const auto& e : prog.sequence)
            if (e.kind == ir::SequenceEntry::Kind::Compound ? prog.compounds[static_cast<std::size_t>(e.index)].matchRule == index
                                                            : e.kind == ir::SequenceEntry::Kind::Rule && e.index == index)
                info.globalMatches = true;
    }
    KindEffects effects = kindEffects(r, prog.kinds);
    info.readKinds = std::move(effects.readKinds);
    info.readsDegrees = effects.readsDegrees;
    info.readsNeighbours = effects.readsNeighbours;
    info.readValues = std::move(effects.readValues);
    for (const auto& d : daughters) {
        info.changedKinds.push_back(d.effects.changedKinds);
        info.changedValues.push_back(d.effects.changedValues);
        info.deletesNodes.push_back(d.effects.deletesNodes ? 1 : 0);
        if (prog.angleLayout) info.shapes.push_back(d.effects.shape);
    }
    info.intersect = r.intersect;
    info.intersectInPlane = r.intersect && !prog.space3d;
    if ((r.merge || prog.mergeAll) && !r.intersect) {   // a command tests for intersection or merges (G^3 §4.3)
        if (!prog.mergeTolerance) info.mergeTolerance = rt::kDefaultMergeTolerance;
        else if (prog.mergeTolerance->op == ir::ExprOp::Literal) info.mergeTolerance = std::get<double>(prog.mergeTolerance->value);
        else out.startNumbers.push_back({SetRuleNumber::Field::MergeTolerance, -1, &*prog.mergeTolerance, kMergeToleranceCheck});
    }
    return out;
}

RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& r) {
    std::vector<RewriteProgram> daughters;
    for (std::size_t d = 0; d < r.daughters.size(); ++d) daughters.push_back(lowerRewrite(prog, r, d));
    return ruleFacts(prog, r, daughters);
}

}  // namespace g2d::lower
