#pragma once
// A sorted set of kind indices where -1 (a wildcard, or a kind unknown after
// an error) stands for every kind of its class.
#include <set>
#include <vector>

#include "ir/ir.hpp"

namespace g2d::lower {

// A kind's attribute as one number (RuleInfo::readValues, changedValues).
inline long long valueKey(int kind, int attribute) { return static_cast<long long>(kind) << 32 | static_cast<unsigned>(attribute); }

class KindSet {
public:
    explicit KindSet(const std::vector<ir::Kind>& kinds) : kinds_(&kinds) {}
    void add(int kind, ir::ElemClass cls) {
        if (kind >= 0) {
            set_.insert(kind);
            return;
        }
        for (std::size_t k = 0; k < kinds_->size(); ++k)
            if ((*kinds_)[k].cls == cls) set_.insert(static_cast<int>(k));
    }
    std::vector<int> sorted() const { return {set_.begin(), set_.end()}; }

private:
    const std::vector<ir::Kind>* kinds_;
    std::set<int> set_;
};

}  // namespace g2d::lower
