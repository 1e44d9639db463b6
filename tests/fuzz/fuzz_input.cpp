// A libFuzzer target of one check of reader_checks.hpp, named by the build
// (G2D_FUZZ_CHECK): fuzz_infer_json, fuzz_lsp, ...
#include "reader_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::G2D_FUZZ_CHECK(data, size);
    return 0;
}
