#pragma once
// `g2d emit-cpp`: one self-contained C++ translation unit per grammar. Kinds
// become structs with typed fields, each rule's search plan becomes nested
// loops over the runtime's indexes, daughters become straight-line rewrite
// code, and expressions become C++. It includes only the runtime's public
// headers and runs through the runtime's driver, like `g2d run`.
#include <string>

#include "diag/source.hpp"
#include "ir/ir.hpp"

namespace g2d::emit {

struct EmitOptions {
    std::string grammarFile;             // as `g2d run` would be given it
    const SourceManager* sources = nullptr;
    bool withMain = true;                // a program; otherwise only the factory
    std::string factoryName = "g2d_make_grammar";
};

std::string emitCpp(const ir::Program& prog, const EmitOptions& options);

}  // namespace g2d::emit
