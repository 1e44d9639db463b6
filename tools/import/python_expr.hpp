#pragma once
// Python expressions of the original tool's YAML grammars (model_gen), parsed
// and rewritten as g2d expressions. The caller says what each name means; this
// file knows Python's syntax and the tool's library (Vec, norm, rotate, random…).

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace g2d::import {

enum class PyType { Unknown, Bool, Int, Float, String, Vec2, None };

// What a bare name in an expression stands for.
struct PyBinding {
    enum class Kind {
        Value,      // a value: `text` is its g2d expression (a let, a const, a vector)
        Element,    // a matched graph element: `text` is its g2d name
        Placed,     // `self_`: the element being placed; as a position, g2d's `placed`
    };
    Kind kind = Kind::Value;
    std::string text;
    PyType type = PyType::Unknown;  // for Value
    bool isNode = true;             // for Element
};

struct PyContext {
    // A name's meaning, or nullopt when the name is not one of the grammar's.
    // Python's and the tool's own names (pi, random, np, Vec, norm, …) are known
    // to the translator and asked only when the caller binds them first.
    std::function<std::optional<PyBinding>(std::string_view name)> lookup;
    // The g2d type of an attribute of an element (node or edge), Unknown if the
    // grammar has no such attribute.
    std::function<PyType(bool isNode, std::string_view key)> attributeType;
    // In a mother condition: `attr` is this element's value of this key, and
    // `attrs['k']` reads the element's other attributes. Empty elsewhere.
    std::string conditionElement;
    bool conditionElementIsNode = true;
    std::string conditionKey;
};

struct PyTranslation {
    bool ok = false;
    std::string text;          // the g2d expression when ok
    PyType type = PyType::Unknown;
    std::string problem;       // why not, when !ok: one line, says what to write instead if known
    int column = 0;            // 0-based column of the problem in the source text
};

PyTranslation translatePython(std::string_view source, const PyContext& context);

std::string_view pyTypeName(PyType type);

}  // namespace g2d::import
