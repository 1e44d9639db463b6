#pragma once
// What the fuzz targets check, shared by the libFuzzer targets (scripts/fuzz.sh)
// and by the replay test that runs every saved input in the normal suite.
//
// Each check returns normally for any input the tool handles as it should
// (a result, or a clear error) and aborts with a message on anything else:
// an internal error (std::logic_error), an error without a location, a
// diagnostic pointing outside the file, a result despite errors. Crashes,
// hangs and memory errors are found by the sanitizers and libFuzzer itself.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>

#include "front/compile.hpp"
#include "g2d/grammar_run.hpp"

namespace g2d::fuzz {

// Reports a fault of g2d's and aborts (libFuzzer keeps the input).
[[noreturn]] void violated(const std::string& what);

// A compilation's diagnostics are located, in range and consistent with
// whether it made a program.
void checkDiagnostics(const CompileResult& r);

// The front end (load, parse, analyse) on arbitrary bytes.
void checkFrontEnd(const std::uint8_t* data, std::size_t size);

// The interpreter on inputs that pass the front end: derived under step,
// element and time budgets with incremental matching verified after every
// step, then drawn and written as SVG and JSON.
void checkInterpreter(const std::uint8_t* data, std::size_t size);

// The same, on the calling thread (the two above run them on a thread with
// the stack g2d itself runs on: driver/big_stack.hpp).
void checkFrontEndHere(const std::uint8_t* data, std::size_t size);
void checkInterpreterHere(const std::uint8_t* data, std::size_t size);

// Why `e`, ending a run (or its drawing) of `run`, is a fault of g2d's rather
// than an error it reports: only a bound (rt::RunawayError) or a run-time
// error located in the grammar's source may end a run. Nullopt when it may.
std::optional<std::string> unexpectedRunFailure(const std::exception& e, const rt::GrammarRun& run);

}  // namespace g2d::fuzz
