#include "g2d/operators.hpp"

#include <stdexcept>

#include "g2d/ops.hpp"

namespace g2d::rt {

namespace {

// Value's alternatives, by index (value.hpp).
constexpr std::size_t kInt = 0, kFloat = 1, kString = 3, kVec = 4, kVec3 = 6;

[[noreturn]] void notAllowed() { throw std::logic_error("binaryOp: operands of types the checker does not allow"); }

}  // namespace

Value binaryOp(BinaryOp op, const Value& l, const Value& r) {
    if (op == BinaryOp::Eq) return l == r;
    if (op == BinaryOp::Ne) return l != r;
    const std::size_t lt = l.index(), rt = r.index();
    if (lt == kInt && rt == kInt) {
        const long long a = *std::get_if<kInt>(&l), b = *std::get_if<kInt>(&r);
        switch (op) {
        case BinaryOp::Add: return addInt(a, b);
        case BinaryOp::Sub: return subInt(a, b);
        case BinaryOp::Mul: return mulInt(a, b);
        case BinaryOp::Mod: return modInt(a, b);
        case BinaryOp::Lt: return a < b;
        case BinaryOp::Le: return a <= b;
        case BinaryOp::Gt: return a > b;
        case BinaryOp::Ge: return a >= b;
        default: notAllowed();
        }
    }
    if (lt == kFloat && rt == kFloat) {
        const double a = *std::get_if<kFloat>(&l), b = *std::get_if<kFloat>(&r);
        switch (op) {
        case BinaryOp::Add: return finite(a + b);
        case BinaryOp::Sub: return finite(a - b);
        case BinaryOp::Mul: return finite(a * b);
        case BinaryOp::Div: return divFloat(a, b);
        case BinaryOp::Mod: return modFloat(a, b);
        case BinaryOp::Lt: return a < b;
        case BinaryOp::Le: return a <= b;
        case BinaryOp::Gt: return a > b;
        case BinaryOp::Ge: return a >= b;
        default: notAllowed();
        }
    }
    if (lt == kVec && rt == kVec) {
        if (op == BinaryOp::Add) return finite(*std::get_if<kVec>(&l) + *std::get_if<kVec>(&r));
        if (op == BinaryOp::Sub) return finite(*std::get_if<kVec>(&l) - *std::get_if<kVec>(&r));
    } else if (lt == kVec && rt == kFloat) {
        if (op == BinaryOp::Mul) return finite(*std::get_if<kVec>(&l) * *std::get_if<kFloat>(&r));
        if (op == BinaryOp::Div) return divVec(*std::get_if<kVec>(&l), *std::get_if<kFloat>(&r));
    } else if (lt == kFloat && rt == kVec && op == BinaryOp::Mul) {
        return finite(*std::get_if<kFloat>(&l) * *std::get_if<kVec>(&r));
    } else if (lt == kVec3 && rt == kVec3) {
        if (op == BinaryOp::Add) return finite(*std::get_if<kVec3>(&l) + *std::get_if<kVec3>(&r));
        if (op == BinaryOp::Sub) return finite(*std::get_if<kVec3>(&l) - *std::get_if<kVec3>(&r));
    } else if (lt == kVec3 && rt == kFloat) {
        if (op == BinaryOp::Mul) return finite(*std::get_if<kVec3>(&l) * *std::get_if<kFloat>(&r));
        if (op == BinaryOp::Div) return divVec(*std::get_if<kVec3>(&l), *std::get_if<kFloat>(&r));
    } else if (lt == kFloat && rt == kVec3 && op == BinaryOp::Mul) {
        return finite(*std::get_if<kFloat>(&l) * *std::get_if<kVec3>(&r));
    } else if (lt == kString && rt == kString && op == BinaryOp::Add) {
        return *std::get_if<kString>(&l) + *std::get_if<kString>(&r);
    }
    notAllowed();
}


}  // namespace g2d::rt
