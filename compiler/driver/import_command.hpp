#pragma once
// `g2d import FILE.yml -o FILE.g2d`: a grammar of the original tool as g2d source.
#include <string>

namespace g2d {

struct ImportCommandOptions {
    std::string input;        // the tool's YAML grammar
    std::string output;       // -o: the .g2d file (whole or not at all); stdout without it
    bool quiet = false;       // no warnings on stderr
};

int runImport(const ImportCommandOptions& options);

}  // namespace g2d
