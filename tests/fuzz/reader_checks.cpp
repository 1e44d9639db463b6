#include "reader_checks.hpp"

#include <cmath>
#include <functional>
#include <string>

#include "driver/big_stack.hpp"
#include "front/compile.hpp"
#include "front/reserved_names.hpp"
#include "fuzz_checks.hpp"
#include "import/model_gen_grammar.hpp"
#include "import/model_gen_import.hpp"
#include "import/python_expr.hpp"
#include "import/python_parse.hpp"
#include "infer/example_json.hpp"
#include "infer/example_svg.hpp"
#include "infer/grammar_inference.hpp"
#include "infer/labelled_example.hpp"
#include "infer/svg_syntax.hpp"

namespace g2d::fuzz {

namespace {

std::string textOf(const std::uint8_t* data, std::size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

int lineCount(const std::string& text) {
    int lines = 1;
    for (char c : text) lines += c == '\n';
    return lines;
}

// "PATH:..." or "PATH: ...", with something said after it.
void checkLocated(const std::string& message, const std::string& path) {
    if (message.rfind(path, 0) != 0 || message.size() < path.size() + 3 || message[path.size()] != ':')
        violated("an error that does not say where: " + message);
}

void checkShape(const infer::ExampleShape& shape) {
    if (shape.edges.empty()) violated("an example without edges was read");
    if (shape.brushes.empty()) violated("an example without edge labels was read");
    for (const auto& p : shape.vertices)
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) violated("a vertex at a non-finite position was read");
    const int nv = static_cast<int>(shape.vertices.size()), nb = static_cast<int>(shape.brushes.size()),
              na = static_cast<int>(shape.areas.size());
    for (const auto& e : shape.edges) {
        if (e.from < 0 || e.to < 0 || e.from >= nv || e.to >= nv) violated("an edge end out of range was read");
        if (e.brush < 0 || e.brush >= nb) violated("an edge label out of range was read");
        if (e.leftArea < -1 || e.rightArea < -1 || e.leftArea >= na || e.rightArea >= na)
            violated("an area label out of range was read");
    }
    for (const auto& b : shape.brushes)
        if (!std::isfinite(b.minLength) || !std::isfinite(b.maxLength) || !std::isfinite(b.unit) || !std::isfinite(b.bend))
            violated("a non-finite edge label setting was read");
}

// Reading, labelling and, for an example small enough to take milliseconds,
// inference: each ends in a result or a located InputError.
void checkExample(const std::string& path, const std::function<infer::ExampleShape()>& read) {
    infer::ExampleShape shape;
    try {
        shape = read();
    } catch (const infer::InputError& e) {
        checkLocated(e.message, path);
        return;
    } catch (const std::exception& e) {
        violated(std::string("the reader threw: ") + e.what());
    }
    checkShape(shape);
    try {
        const infer::LabelledExample ex = infer::labelExample(shape);
        if (shape.edges.size() <= 24) {
            infer::InferOptions options;
            options.maxGraphs = 200;
            (void)infer::inferGrammar(ex, options);
        }
    } catch (const infer::InputError& e) {
        checkLocated(e.message, path);
    } catch (const std::exception& e) {
        violated(std::string("labelling or inference threw: ") + e.what());
    }
}

void checkNumbers(const std::vector<double>& numbers) {
    for (double v : numbers)
        if (!std::isfinite(v)) violated("a non-finite number was read");
}

}  // namespace

void checkInferJson(const std::uint8_t* data, std::size_t size) {
    const std::string text = textOf(data, size), path = "input.json";
    runWithBigStack([&] {
        checkExample(path, [&] { return infer::readExampleJson(text, path); });
        return 0;
    });
}

void checkInferSvg(const std::uint8_t* data, std::size_t size) {
    const std::string text = textOf(data, size), path = "input.svg";
    runWithBigStack([&] {
        checkExample(path, [&] { return infer::readExampleSvg(text, path); });
        return 0;
    });
}

void checkSvgAttribute(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return;
    const std::string text = textOf(data + 1, size - 1);
    try {
        switch (data[0] % 5) {
        case 0:
            if (auto v = infer::svg::parseLength(text)) checkNumbers({*v});
            break;
        case 1: checkNumbers(infer::svg::parseNumberList(text)); break;
        case 2: {
            const infer::svg::Matrix m = infer::svg::parseTransform(text);
            checkNumbers({m.a, m.b, m.c, m.d, m.e, m.f});
            break;
        }
        case 3:
            for (const auto& sub : infer::svg::parsePathData(text)) {
                if (sub.points.empty()) violated("an empty subpath");
                for (const auto& p : sub.points) checkNumbers({p.x, p.y});
            }
            break;
        default:
            if (auto c = infer::svg::parseColor(text))
                if (c->size() != 7 || (*c)[0] != '#' || c->find_first_not_of("0123456789abcdef", 1) != std::string::npos)
                    violated("a colour that is not #rrggbb: " + *c);
        }
    } catch (const infer::svg::SyntaxError& e) {
        if (e.message.empty()) violated("a syntax error without a message");
    } catch (const std::exception& e) {
        violated(std::string("an attribute parser threw: ") + e.what());
    }
}

void checkImportYaml(const std::uint8_t* data, std::size_t size) {
    const std::string text = textOf(data, size);
    const int lines = lineCount(text);
    runWithBigStack([&] {
        import::ImportedGrammar imported;
        try {
            imported = import::importModelGen(import::readModelGenGrammar(text), "input.yml",
                                                  {front::reservedNames(), front::attributeNamesRefused(), front::keywordNames()});
        } catch (const import::MgError& e) {
            if (e.line < 1 || e.line > lines) violated("an import error on line " + std::to_string(e.line) + " of " + std::to_string(lines));
            if (std::string(e.what()).empty()) violated("an import error without a message");
            return 0;
        } catch (const std::exception& e) {
            violated(std::string("the import threw: ") + e.what());
        }
        for (const auto& w : imported.warnings)
            if (w.line < 0 || w.line > lines || w.message.empty()) violated("a warning out of place: " + w.message);
        // What the importer writes is a grammar: what it cannot translate is
        // a TODO comment and a warning, never g2d that does not compile.
        const CompileResult compiled = compileSource("/nonexistent-g2d-fuzz/imported.g2d", imported.source, LoadOptions{});
        checkDiagnostics(compiled);
        if (!compiled.program)
            for (const auto& d : compiled.diags.sorted())
                if (d.severity == Severity::Error)
                    violated("the import wrote a grammar with an error: " + std::to_string(d.span.line) + ": " + d.message);
        return 0;
    });
}

void checkPythonExpression(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return;
    const int mode = data[0] % 3;
    const std::string text = textOf(data + 1, size - 1);
    using import::PyBinding;
    using import::PyType;
    import::PyContext context;
    context.lookup = [mode](std::string_view name) -> std::optional<PyBinding> {
        if (name == "a" || name == "b") return PyBinding{PyBinding::Kind::Value, std::string(name), PyType::Float, true};
        if (name == "k") return PyBinding{PyBinding::Kind::Value, "k", PyType::Int, true};
        if (name == "s") return PyBinding{PyBinding::Kind::Value, "s", PyType::String, true};
        if (name == "v") return PyBinding{PyBinding::Kind::Value, "v", PyType::Vec2, true};
        if (name == "n" || name == "old") return PyBinding{PyBinding::Kind::Element, "n", PyType::Unknown, true};
        if (name == "e") return PyBinding{PyBinding::Kind::Element, "e", PyType::Unknown, false};
        if (name == "self_" && mode == 2) return PyBinding{PyBinding::Kind::Placed, "placed", PyType::Vec2, true};
        return std::nullopt;
    };
    context.attributeType = [](bool, std::string_view key) {
        if (key == "label") return PyType::String;
        if (key == "length" || key == "angle") return PyType::Float;
        if (key == "count") return PyType::Int;
        if (key == "flag") return PyType::Bool;
        if (key == "dir") return PyType::Vec2;
        return PyType::Unknown;
    };
    if (mode == 0) {
        context.conditionElement = "n";
        context.conditionKey = "label";
    }
    runWithBigStack([&] {
        try {
            const import::py::ParseResult parsed = import::py::parsePython(text);
            if (!parsed.root && parsed.problem.empty()) violated("a parse without a tree or a problem");
            const import::PyTranslation t = import::translatePython(text, context);
            if (t.ok && t.text.empty()) violated("an empty translation");
            if (!t.ok) {
                if (t.problem.empty()) violated("an untranslatable expression without a reason");
                if (t.problem.find('\n') != std::string::npos) violated("a reason of more than one line: " + t.problem);
                if (t.column < 0 || t.column > static_cast<int>(text.size()))
                    violated("a problem at column " + std::to_string(t.column) + " of " + std::to_string(text.size()));
            }
        } catch (const std::exception& e) {
            violated(std::string("the Python translator threw: ") + e.what());
        }
        return 0;
    });
}

}  // namespace g2d::fuzz
