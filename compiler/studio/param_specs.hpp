#pragma once
// The grammar's `param` declarations as the page's parameters panel reads
// them: [{"name", "type", "type_name", "default", "values"?, "min"?, "max"?, "step"?}].
#include <vector>

#include <nlohmann/json.hpp>

#include "g2d/grammar_run.hpp"

namespace g2d::studio {

nlohmann::json paramSpecsJson(const std::vector<rt::ParamSpec>& specs);

}  // namespace g2d::studio
