#pragma once
// What the element facts an expression reads depend on, from the fact
// table's `reads` column (g2d/element_facts.hpp): the one place that says
// which changes of the graph can change a fact. Kind effects, the search
// plan's incidence readers and the near-negative index all ask here, so a
// new fact needs no list of its own in the lowering.
#include <cstdint>
#include <vector>

#include "g2d/element_facts.hpp"
#include "ir/ir.hpp"

namespace g2d::lower {

// The bits that read elements other than the one the fact is of.
inline constexpr std::uint8_t kReadsOthers =
    rt::kReadsEnds | rt::kReadsEdgesAt | rt::kReadsFacesAt | rt::kReadsFaceSides | rt::kReadsCorners;

// Calls f(fact expression, its kReads* bits) for every ExprOp::Fact in `e`.
template <class F>
void eachFact(const ir::Expr& e, const F& f) {
    if (e.op == ir::ExprOp::Fact) f(e, rt::elementFactEntry(e.fact).reads);
    for (const auto& a : e.args) eachFact(a, f);
}

// The union of the kReads* bits of the facts `e` reads (of any element).
std::uint8_t factReads(const ir::Expr& e);
std::uint8_t factReads(const std::vector<ir::Condition>& conditions);

}  // namespace g2d::lower
