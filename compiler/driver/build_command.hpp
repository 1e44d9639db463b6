#pragma once
// `g2d emit-cpp FILE -o OUT.cpp` and `g2d build FILE -o EXE [--cxx C] [-O N]`.
#include <optional>
#include <string>

namespace g2d {

struct BuildOptions {
    std::string file;
    std::string output;                  // the .cpp (emit-cpp) or the executable (build)
    std::optional<std::string> cxx;      // default: $CXX, then c++
    std::string optimize = "2";
    std::optional<std::string> keepCpp;  // build: also write the generated C++ here
    bool verbose = false;
    bool withMain = true;                // emit-cpp: a program, or only the factory
    std::string factory = "g2d_make_grammar";
};

int runEmitCpp(const BuildOptions& options);
int runBuild(const BuildOptions& options);

}  // namespace g2d
