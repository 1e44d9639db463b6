#pragma once
// `g2d show FILE -o OUT.html|OUT.svg`: the productions as diagrams.
#include <string>

namespace g2d {

struct ShowOptions {
    std::string file;
    std::string output;   // .svg: the diagram alone; otherwise an HTML page
};

// Returns the exit code: 0 done, 1 errors in the grammar or the output.
int runShow(const ShowOptions& options);

}  // namespace g2d
