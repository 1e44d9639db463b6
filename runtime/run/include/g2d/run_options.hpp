#pragma once
// The options of a run, one set for `g2d run FILE` and for compiled programs
// (so both accept the same words, with the same help), read with CLI11.
#include <optional>
#include <string>
#include <vector>

#include "g2d/grammar_run.hpp"
#include "g2d/run_driver.hpp"

namespace CLI {
class App;
}

namespace g2d::rt {

// Adds every run option to `app` (the `run` subcommand, or a compiled
// program's whole command line), bound to `request`.
void addRunOptions(CLI::App& app, RunRequest& request);

// The grammar's parameters for --help: one line each, `  -D NAME=TYPE   (default: VALUE)`.
std::string parameterHelp(const std::vector<ParamSpec>& params);

// For compiled programs: reads the command line into a request. Returns an
// exit code (0 after --help, 2 on a usage error) when the program should stop.
std::optional<int> parseRunArguments(int argc, char** argv, const std::string& grammarFile,
                                     const std::vector<ParamSpec>& params, RunRequest& out);

}  // namespace g2d::rt
