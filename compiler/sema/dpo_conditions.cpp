#include "sema/dpo_conditions.hpp"

#include <algorithm>

namespace g2d::sema {

void addDanglingConditions(ir::Rule& rule) {
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        const int node = static_cast<int>(i);
        const bool deleted = std::any_of(rule.daughters.begin(), rule.daughters.end(), [&](const ir::Daughter& d) {
            return std::find(d.deletedNodes.begin(), d.deletedNodes.end(), node) != d.deletedNodes.end();
        });
        if (!deleted) continue;
        const auto edges = std::count_if(rule.edges.begin(), rule.edges.end(),
                                         [&](const ir::PatternEdge& e) { return e.src == node || e.dst == node; });
        const Span at = rule.nodes[i].span;
        ir::Expr degree;
        degree.op = ir::ExprOp::Fact;
        degree.type = ir::Type::of(ir::TypeKind::Int);
        degree.span = at;
        degree.elem = ir::ElemRef{ir::ElemClass::Node, node};
        degree.fact = ir::ElemFact::Degree;
        ir::Expr count;
        count.type = ir::Type::of(ir::TypeKind::Int);
        count.span = at;
        count.value = static_cast<long long>(edges);
        ir::Expr same;
        same.op = ir::ExprOp::Eq;
        same.type = ir::kBoolType;
        same.span = at;
        same.args.push_back(std::move(degree));
        same.args.push_back(std::move(count));
        rule.conditions.push_back(ir::Condition{std::move(same), {ir::ElemRef{ir::ElemClass::Node, node}}});
    }
}

}  // namespace g2d::sema
