#pragma once
// RuleSet's applied hook for the length of a scope.
#include <functional>
#include <utility>

#include "g2d/derivation.hpp"

namespace g2d::rt {

// Sets the rules' applied hook for a scope and puts back the hook it
// replaced, however the scope ends.
class AppliedHook {
public:
    AppliedHook(RuleSet& rules, std::function<void()> hook) : rules_(rules), previous_(rules.appliedHook()) {
        rules_.setAppliedHook(std::move(hook));
    }
    ~AppliedHook() { rules_.setAppliedHook(std::move(previous_)); }
    AppliedHook(const AppliedHook&) = delete;
    AppliedHook& operator=(const AppliedHook&) = delete;

private:
    RuleSet& rules_;
    std::function<void()> previous_;
};

}  // namespace g2d::rt
