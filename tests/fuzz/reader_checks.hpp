#pragma once
// What the fuzz targets of g2d's other inputs check (docs/robustness.md):
// the example readers of `g2d infer` (the author's JSON, SVG drawings and
// their attribute syntaxes), `g2d import`'s YAML reader and Python
// expression translator, and `g2d lsp`'s message handling. Like
// fuzz_checks.hpp: each returns for a result or a located error and aborts
// on anything else.
#include <cstddef>
#include <cstdint>

namespace g2d::fuzz {

// readExampleJson, then labelling and (for small examples) inference.
void checkInferJson(const std::uint8_t* data, std::size_t size);
// readExampleSvg, then the same.
void checkInferSvg(const std::uint8_t* data, std::size_t size);
// The SVG attribute parsers alone: the first byte picks one (length, number
// list, transform, path data, colour), the rest is the attribute's text.
void checkSvgAttribute(const std::uint8_t* data, std::size_t size);
// readModelGenGrammar and importModelGen; what is imported must compile
// without errors.
void checkImportYaml(const std::uint8_t* data, std::size_t size);
// One Python expression, parsed and translated in a grammar-like context
// the first byte picks (a mother condition, a var_calc, a daughter attribute).
void checkPythonExpression(const std::uint8_t* data, std::size_t size);
// A session of JSON-RPC messages (lsp_checks.cpp).
void checkLanguageServer(const std::uint8_t* data, std::size_t size);
// A random plane drawing the bytes describe, inferred from (inference_checks.cpp).
void checkInferenceOnDrawing(const std::uint8_t* data, std::size_t size);

}  // namespace g2d::fuzz
