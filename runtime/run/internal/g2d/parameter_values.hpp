#pragma once
// A run's parameter values: the grammar's defaults, then overrides written
// NAME=VALUE as `-D` takes them (`g2d run`, compiled programs, `g2d studio`).
#include <string>
#include <vector>

#include "g2d/grammar_run.hpp"

namespace g2d::rt {

// Fills `out` with one value per spec. Returns what is wrong with an
// override (an unknown name, a value not of the parameter's type or outside
// its declared range), or "". The words name no `-D`: the studio says them too.
std::string parameterValues(const std::vector<ParamSpec>& specs, const std::vector<std::string>& defines,
                            std::vector<Value>& out);

}  // namespace g2d::rt
