#include "lower/near_negative.hpp"

#include "lower/fact_reads.hpp"

#include <algorithm>
#include <vector>

namespace g2d::lower {

namespace {

bool readsNode(const ir::Expr& e, int node) {
    if ((e.op == ir::ExprOp::Attr || e.op == ir::ExprOp::Fact) && e.elem.cls == ir::ElemClass::Node && e.elem.index == node)
        return true;
    for (const auto& a : e.args)
        if (readsNode(a, node)) return true;
    return false;
}

// Whether `e` reads something of node `node` that its position, attributes,
// age, generation, id and radius do not show (what the spatial index does not follow).
bool readsIncidence(const ir::Expr& e, int node) {
    bool reads = false;
    eachFact(e, [&](const ir::Expr& f, std::uint8_t factReads) {
        reads = reads || (f.elem.cls == ir::ElemClass::Node && f.elem.index == node && (factReads & kReadsOthers));
    });
    return reads;
}

bool isPosOf(const ir::Expr& e, int node) {
    return e.op == ir::ExprOp::Fact && e.elem.cls == ir::ElemClass::Node && e.elem.index == node &&
           (e.fact == ir::ElemFact::Pos || e.fact == ir::ElemFact::Pos3);
}

void conjuncts(const ir::Expr& e, std::vector<const ir::Expr*>& out) {
    if (e.op == ir::ExprOp::And && e.args.size() == 2) {
        conjuncts(e.args[0], out);
        conjuncts(e.args[1], out);
    } else {
        out.push_back(&e);
    }
}

// `distance(o.pos, P) < R` and its mirrored spellings.
std::optional<NearNegative> distanceTest(const ir::Expr& e, int node) {
    bool inclusive = false;
    const ir::Expr *call = nullptr, *radius = nullptr;
    if (e.args.size() != 2) return std::nullopt;
    switch (e.op) {
    case ir::ExprOp::Le: inclusive = true; [[fallthrough]];
    case ir::ExprOp::Lt: call = &e.args[0], radius = &e.args[1]; break;
    case ir::ExprOp::Ge: inclusive = true; [[fallthrough]];
    case ir::ExprOp::Gt: call = &e.args[1], radius = &e.args[0]; break;
    default: return std::nullopt;
    }
    if (call->op != ir::ExprOp::Call || call->args.size() != 2 ||
        (call->builtin != ir::Builtin::Distance && call->builtin != ir::Builtin::Distance3))
        return std::nullopt;
    const ir::Expr* centre = isPosOf(call->args[0], node) ? &call->args[1] : isPosOf(call->args[1], node) ? &call->args[0] : nullptr;
    if (!centre || readsNode(*centre, node) || readsNode(*radius, node)) return std::nullopt;
    return NearNegative{node, -1, centre, radius, inclusive, 0};
}

// The nodes `e` reads; an edge or face read counts as node -1 (never bound here).
void nodesRead(const ir::Expr& e, std::vector<int>& out) {
    if (e.op == ir::ExprOp::Attr || e.op == ir::ExprOp::Fact) out.push_back(e.elem.cls == ir::ElemClass::Node ? e.elem.index : -1);
    for (const auto& a : e.args) nodesRead(a, out);
}

}  // namespace

std::optional<NearNegative> nearJoin(const std::vector<ir::Condition>& conditions, const ir::PatternNode& node, int index,
                                     const std::function<bool(int)>& bound) {
    for (const auto& c : conditions) {
        std::vector<const ir::Expr*> parts;
        conjuncts(c.expr, parts);
        for (const ir::Expr* p : parts) {
            auto test = distanceTest(*p, index);
            if (!test) continue;
            std::vector<int> read;
            nodesRead(*test->centre, read);
            nodesRead(*test->radius, read);
            if (read.empty() || !std::all_of(read.begin(), read.end(), [&](int n) { return n >= 0 && bound(n); })) continue;
            test->kind = node.kind;
            test->key = read.front();
            return test;
        }
    }
    return std::nullopt;
}

std::optional<NearNegative> nearNegative(const ir::Rule& rule, std::size_t index) {
    if (rule.nodes.empty() || index >= rule.nacs.size()) return std::nullopt;
    const ir::NegativeCondition& nac = rule.nacs[index];
    if (nac.nodes.size() != 1 || !nac.edges.empty() || !nac.faces.empty() || nac.nodes[0].kind < 0) return std::nullopt;
    const int node = nac.outerNodes;
    std::optional<NearNegative> found;
    for (const auto& c : nac.conditions) {
        if (readsIncidence(c.expr, node)) return std::nullopt;
        std::vector<const ir::Expr*> parts;
        conjuncts(c.expr, parts);
        for (const ir::Expr* p : parts)
            if (!found) found = distanceTest(*p, node);
    }
    if (!found) return found;
    found->kind = nac.nodes[0].kind;
    for (int n = 0; n < nac.outerNodes; ++n)
        if (readsNode(*found->centre, n) || readsNode(*found->radius, n)) {
            found->key = n;
            break;
        }
    return found;
}

}  // namespace g2d::lower
