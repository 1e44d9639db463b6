// libFuzzer target 1: the front end on arbitrary bytes.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    g2d::fuzz::checkFrontEnd(data, size);
    return 0;
}
