#pragma once
// A rule's rt::RuleInfo as C++ statements (`info.FIELD = …;`), one per field
// of rt::eachRuleInfoField: the generated grammar holds the data the
// lowering made, the same the interpreter uses.
#include <string>

#include "g2d/rule_info.hpp"

namespace g2d::emit {

std::string ruleInfoText(const rt::RuleInfo& info, const std::string& in);

}  // namespace g2d::emit
