#include "lower/fact_reads.hpp"

namespace g2d::lower {

std::uint8_t factReads(const ir::Expr& e) {
    std::uint8_t bits = 0;
    eachFact(e, [&](const ir::Expr&, std::uint8_t reads) { bits |= reads; });
    return bits;
}

std::uint8_t factReads(const std::vector<ir::Condition>& conditions) {
    std::uint8_t bits = 0;
    for (const auto& c : conditions) bits |= factReads(c.expr);
    return bits;
}

}  // namespace g2d::lower
