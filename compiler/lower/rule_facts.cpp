#include "lower/rule_facts.hpp"

// The IR's edge-list bits are the runtime's (ir::Rule::readDirections is
// handed over as is).
static_assert(g2d::ir::kReadsOutEdges == g2d::rt::RepairArea::kOut && g2d::ir::kReadsInEdges == g2d::rt::RepairArea::kIn);

namespace g2d::lower {

namespace {

rt::Incidence incidence(ir::IncidenceRead r) {
    switch (r) {
    case ir::IncidenceRead::None: return rt::Incidence::None;
    case ir::IncidenceRead::PatternEdges: return rt::Incidence::PatternEdges;
    case ir::IncidenceRead::AllEdges: return rt::Incidence::AllEdges;
    }
    return rt::Incidence::AllEdges;
}

}  // namespace

RuleFacts ruleFacts(const ir::Program& prog, const ir::Rule& r) {
    RuleFacts out;
    rt::RuleInfo& info = out.info;
    info.name = r.name;
    info.priority = r.priority;
    info.pick = r.pick == ir::Pick::Oldest ? rt::Pick::Oldest : rt::Pick::Random;
    // `parallel` on the rule, or on its priority (`priority P parallel;`).
    const auto prio = prog.priorities.find(r.priority);
    info.parallel = r.parallel || (prio != prog.priorities.end() && prio->second.parallel);
    for (const auto& d : r.daughters) {
        info.weights.push_back(d.weight ? *d.weight : d.weightExpr ? 0.0 : 1.0);
        out.weightExprs.push_back(!d.weight && d.weightExpr ? &*d.weightExpr : nullptr);
    }
    info.radius = r.repairRadius;
    for (ir::IncidenceRead read : r.readsIncidence) info.readsIncidence.push_back(incidence(read));
    info.readDirections = r.readDirections;
    for (bool nothing : r.newHostAddsNothing) info.newHostAddsNothing.push_back(nothing ? 1 : 0);
    for (const auto& n : r.nodes) info.nodeKinds.push_back(n.kind);
    info.edgeCount = static_cast<int>(r.edges.size());
    info.kindsKnown = true;
    info.readKinds = r.readKinds;
    info.readsDegrees = r.readsDegrees;
    info.readValues = r.readValues;
    for (const auto& d : r.daughters) {
        info.changedKinds.push_back(d.changedKinds);
        info.changedValues.push_back(d.changedValues);
        info.deletesNodes.push_back(d.deletedNodes.empty() ? 0 : 1);
    }
    return out;
}

}  // namespace g2d::lower
