#pragma once
// `g2d run FILE [-o OUT.svg] [--json OUT.json] [--seed N] [-D NAME=VALUE]… [--steps N] [--stats]`
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace g2d {

struct RunOptions {
    std::string file;
    std::optional<std::string> svgOut;     // default: the grammar's name with .svg, in the current folder
    std::optional<std::string> jsonOut;
    std::uint64_t seed = 1;
    std::vector<std::string> defines;      // NAME=VALUE
    std::optional<long long> steps;        // overrides the grammar's global limit
    bool stats = false;
    bool noSvg = false;
    std::optional<long long> maxElements;  // the runaway guard (default: rt::kDefaultMaxElements)
    std::optional<double> timeoutSeconds;  // wall time of the derivation
    bool keepPartial = false;              // write the last completed step after an error or a bound
    std::optional<std::string> traceHtml, traceJson;   // the derivation step by step
};

// Returns the exit code: 0 done, 1 errors in the grammar, the run or the
// outputs, 2 bad arguments.
int runRun(const RunOptions& options);

}  // namespace g2d
