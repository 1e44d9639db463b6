// Bad input never crashes the front end: it gets a clear error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "driver/big_stack.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

// Compiled on the big stack every command of g2d runs its passes on
// (driver/big_stack.hpp): what is tested is what the program does, also
// under AddressSanitizer, whose frames no main-thread stack holds 4000 deep.
std::string firstErrorOfFile(const std::string& path) {
    std::string first;
    runWithBigStack([&] {
        LoadOptions options;
        auto r = compileFile(path, options);
        for (const auto& d : r.diags.sorted())
            if (d.severity == Severity::Error) {
                std::string loc = d.span.line ? std::to_string(d.span.line) + ":" + std::to_string(d.span.col) + ": " : "";
                first = loc + d.message;
                break;
            }
        return 0;
    });
    return first;
}

std::string writeTemp(const std::string& name, const std::string& bytes) {
    auto dir = std::filesystem::temp_directory_path() / "g2d-robustness";
    std::filesystem::create_directories(dir);
    auto path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

}  // namespace

TEST_CASE("missing files, directories and empty files", "[robustness]") {
    CHECK(firstErrorOfFile("/nonexistent/x.g2d") == "cannot open `/nonexistent/x.g2d`: no such file");
    auto dir = std::filesystem::temp_directory_path().string();
    CHECK(firstErrorOfFile(dir) == "cannot read `" + dir + "`: it is a directory, not a .g2d file");
    CHECK(firstErrorOfFile(writeTemp("empty.g2d", "")) ==
          "the grammar has no `axiom { … }`: there is no graph to start from");
}

TEST_CASE("binary garbage and invalid UTF-8", "[robustness]") {
    CHECK(firstErrorOfFile(writeTemp("nul.g2d", std::string("node P;\nx\0y", 11))) ==
          "2:2: file contains a NUL byte: this looks like a binary file, not g2d source");
    CHECK(firstErrorOfFile(writeTemp("latin1.g2d", "// caf\xe9\n")) ==
          "1:7: invalid UTF-8 (byte 0xE9): g2d source must be UTF-8 text");
    CHECK(firstErrorOfFile(writeTemp("overlong.g2d", "\xc0\xaf")) ==
          "1:1: invalid UTF-8 (byte 0xC0): g2d source must be UTF-8 text");
    std::string garbage;
    for (int i = 1; i < 256; ++i) garbage += static_cast<char>(i % 128 ? i % 128 : 1);
    CHECK_FALSE(firstErrorOfFile(writeTemp("garbage.g2d", garbage)).empty());
}

TEST_CASE("deep nesting and huge expressions are refused, not overflowed", "[robustness]") {
    // (Keywords count as operator tokens, so the limits are reached a little early.)
    const std::string deep = "const x = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";";
    CHECK(firstErrorOfFile(writeTemp("deep.g2d", deep)) == "1:211: nesting is too deep (more than 200 levels)");
    std::string negs = "const x = ";
    for (int i = 0; i < 100000; ++i) negs += "- ";
    CHECK(firstErrorOfFile(writeTemp("negs.g2d", negs + "1;")) ==
          "1:411: too many prefix operators in a row (more than 200)");
    std::string chain = "const x = 1";
    for (int i = 0; i < 100000; ++i) chain += " + 1";
    CHECK(firstErrorOfFile(writeTemp("chain.g2d", chain + ";")) ==
          "1:16005: statement is too long (more than 4000 operators)");
    std::string ternary = "const x = ";
    for (int i = 0; i < 1000; ++i) ternary += "true ? 1 : ";
    CHECK(firstErrorOfFile(writeTemp("ternary.g2d", ternary + "0;")) ==
          "1:2216: conditional expressions are nested too deeply (more than 200)");
    // A long but acceptable chain still compiles.
    std::string ok = "node P;\naxiom { a: P; }\nconst x = 0";
    for (int i = 0; i < 3000; ++i) ok += " + 1";
    CHECK(firstErrorOfFile(writeTemp("long_ok.g2d", ok + ";")) == "");
}

TEST_CASE("files over the size limit are refused", "[robustness]") {
    auto path = writeTemp("huge.g2d", std::string((8u << 20) + 1, ' '));
    CHECK(firstErrorOfFile(path).find("is too large (8388609 bytes; the limit is 8388608)") != std::string::npos);
}
