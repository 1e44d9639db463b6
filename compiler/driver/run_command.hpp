#pragma once
// `g2d run FILE [OPTION]…`: the options are the runtime's (g2d/run_options.hpp),
// shared with compiled programs.
#include <string>

#include "g2d/run_driver.hpp"

namespace g2d {

// Returns the exit code: 0 done, 1 errors in the grammar, the run or the
// outputs, 2 bad arguments.
int runRun(const rt::RunRequest& request);

// After `g2d run FILE --help`: the grammar's parameters, with types and
// defaults (nothing when FILE does not compile; its errors are printed).
int printGrammarParameters(const std::string& file);

}  // namespace g2d
