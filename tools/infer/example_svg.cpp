// Reads an SVG example: walks the XML (libxml2), resolves styles and
// transforms, and hands the drawn outlines to svg_geometry for the graph.
#include "infer/example_svg.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>

#include "infer/svg_geometry.hpp"
#include "infer/svg_syntax.hpp"

namespace g2d::infer {
namespace {

using svg::Matrix;
using svg::SyntaxError;
using svg::UserPoint;

// One example unit is 40 user units: the grid cell (Major Grid Spacing) of
// Merrell's app, which example_json.cpp divides by too, so that a drawing
// reads the same from either format.
constexpr double kUserUnitsPerCell = 40;
// Points closer than this many user units (after transforms) are one vertex:
// an editor's snapping is exact, a hand's placement is not.
constexpr double kMergeDistance = 0.5;
constexpr double kTolerance = kMergeDistance / kUserUnitsPerCell;   // the same in example units

constexpr const char* kSvgNamespace = "http://www.w3.org/2000/svg";

struct XmlStringFree {
    void operator()(xmlChar* s) const { xmlFree(s); }
};
struct XmlDocFree {
    void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
struct XmlContextFree {
    void operator()(xmlParserCtxt* c) const { xmlFreeParserCtxt(c); }
};
using XmlString = std::unique_ptr<xmlChar, XmlStringFree>;

// libxml2 goes on after the first fatal error and keeps only the last one
// (often "Premature end of data"); the first is the one to show.
struct FirstError {
    int line = 0;
    std::string message;
};
void keepFirstError(void* data, xmlErrorPtr e) {
    const auto* context = static_cast<const xmlParserCtxt*>(data);
    auto* first = context ? static_cast<FirstError*>(context->_private) : nullptr;
    if (!first || !e || e->level != XML_ERR_FATAL || !first->message.empty()) return;
    first->line = e->line;
    first->message = e->message ? std::string(svg::trim(e->message)) : "unknown error";
}

std::string tagOf(const xmlNode* n) { return reinterpret_cast<const char*>(n->name); }

// Hand-written files often leave out xmlns; other namespaces are the editor's.
bool isSvgElement(const xmlNode* n) {
    return n->type == XML_ELEMENT_NODE &&
           (n->ns == nullptr || std::strcmp(reinterpret_cast<const char*>(n->ns->href), kSvgNamespace) == 0);
}

std::optional<std::string> attribute(const xmlNode* n, const char* name) {
    const XmlString v(xmlGetNoNsProp(n, reinterpret_cast<const xmlChar*>(name)));
    if (!v) return std::nullopt;
    return std::string(reinterpret_cast<const char*>(v.get()));
}

std::string textOf(const xmlNode* n) {
    const XmlString v(xmlNodeGetContent(n));
    return v ? std::string(svg::trim(reinterpret_cast<const char*>(v.get()))) : std::string();
}

// The declarations of a style="..." attribute, property names in lower case.
std::vector<std::pair<std::string, std::string>> declarations(const std::string& style) {
    std::vector<std::pair<std::string, std::string>> out;
    std::size_t start = 0;
    while (start <= style.size()) {
        const std::size_t end = std::min(style.find(';', start), style.size());
        const std::string_view decl = std::string_view(style).substr(start, end - start);
        if (const std::size_t colon = decl.find(':'); colon != std::string_view::npos) {
            std::string name(svg::trim(decl.substr(0, colon)));
            for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            std::string_view value = svg::trim(decl.substr(colon + 1));
            if (const std::size_t bang = value.find("!important"); bang != std::string_view::npos)
                value = svg::trim(value.substr(0, bang));
            out.emplace_back(name, std::string(value));
        }
        start = end + 1;
    }
    return out;
}

struct Style {
    std::optional<std::string> stroke;            // nullopt: none, SVG's initial stroke
    std::optional<std::string> fill = "#000000";  // SVG's initial fill
    bool evenOdd = false;
};

class SvgReader {
public:
    explicit SvgReader(const std::string& path) : path_(path) {}

    ExampleShape read(const xmlNode* root) {
        if (tagOf(root) != "svg" || !isSvgElement(root)) fail(root, "the root element is <" + tagOf(root) + ">, not <svg>");
        const Style style = styleOf(root, Style{});
        children(root, transformOf(root, Matrix{}), style);

        ExampleShape out;
        out.source = path_;
        for (const xmlNode* c = root->children; c && out.name.empty(); c = c->next)
            if (isSvgElement(c) && tagOf(c) == "title") out.name = textOf(c);
        if (out.name.empty()) out.name = std::filesystem::path(path_).stem().string();
        input_.path = path_;
        input_.tolerance = kTolerance;
        input_.svgUnit = kUserUnitsPerCell;
        svg::planarize(input_, out);
        if (out.edges.empty()) fail(root, "the drawing has no edges: only shapes with a stroke draw them");
        renumber(out);
        return out;
    }

private:
    [[noreturn]] void fail(const xmlNode* n, const std::string& what) const {
        throw InputError{path_ + ":" + std::to_string(xmlGetLineNo(n)) + ": " + what};
    }
    [[noreturn]] void failIn(const xmlNode* n, const std::string& what) const { fail(n, "<" + tagOf(n) + ">: " + what); }

    static bool hidden(const xmlNode* n) {
        const auto display = attribute(n, "display");
        bool none = display && svg::trim(*display) == "none";
        if (const auto style = attribute(n, "style"))
            for (const auto& [name, value] : declarations(*style))
                if (name == "display") none = value == "none";
        return none;
    }

    std::optional<std::string> paint(const xmlNode* n, const std::string& name, const std::string& value) const {
        std::string low(svg::trim(value));
        for (char& c : low) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (low == "none" || low == "transparent") return std::nullopt;
        if (low.rfind("url(", 0) == 0)
            failIn(n, name + " \"" + value + "\": gradients and patterns are not supported, only plain colours");
        if (low == "currentcolor") failIn(n, name + " \"" + value + "\" is not supported, only plain colours");
        if (auto color = svg::parseColor(value)) return color;
        failIn(n, name + " \"" + value + "\" is not a colour");
    }

    void setProperty(Style& s, const xmlNode* n, const std::string& name, const std::string& value) const {
        if (svg::trim(value) == "inherit") return;   // the parent's, which s starts as
        if (name == "stroke") s.stroke = paint(n, name, value);
        if (name == "fill") s.fill = paint(n, name, value);
        if (name == "fill-rule") {
            const std::string_view rule = svg::trim(value);
            if (rule != "nonzero" && rule != "evenodd") failIn(n, "fill-rule \"" + value + "\" is not nonzero or evenodd");
            s.evenOdd = rule == "evenodd";
        }
    }

    // Presentation attributes first: style="..." overrides them, as in CSS.
    Style styleOf(const xmlNode* n, const Style& parent) const {
        Style s = parent;
        for (const char* name : {"stroke", "fill", "fill-rule"})
            if (const auto v = attribute(n, name)) setProperty(s, n, name, *v);
        if (const auto style = attribute(n, "style"))
            for (const auto& [name, value] : declarations(*style)) setProperty(s, n, name, value);
        return s;
    }

    Matrix transformOf(const xmlNode* n, const Matrix& parent) const {
        const auto t = attribute(n, "transform");
        if (!t) return parent;
        try {
            return parent * svg::parseTransform(*t);
        } catch (const SyntaxError& e) {
            failIn(n, "transform \"" + *t + "\": " + e.message);
        }
    }

    void children(const xmlNode* n, const Matrix& ctm, const Style& style) {
        for (const xmlNode* c = n->children; c; c = c->next)
            if (isSvgElement(c)) element(c, ctm, style);
    }

    void element(const xmlNode* n, const Matrix& ctm, const Style& style) {
        static const std::set<std::string> skipped{"defs", "symbol", "clipPath", "mask", "pattern", "marker",
                                                   "metadata", "title", "desc", "linearGradient", "radialGradient",
                                                   "filter"};
        static const std::set<std::string> shapes{"line", "polyline", "polygon", "rect", "path"};
        const std::string tag = tagOf(n);
        if (skipped.count(tag) || hidden(n)) return;
        if (tag == "style" && textOf(n).empty()) return;
        if (tag == "style") fail(n, "<style> sheets are not supported: give colours as attributes or in style=\"...\"");
        if (tag == "svg") fail(n, "a nested <svg> is not supported");
        if (tag == "use") fail(n, "<use> is not supported: turn clones into plain shapes (Inkscape: Edit > Clone > Unlink Clone)");
        if (tag == "text" || tag == "image") fail(n, "<" + tag + "> is not supported: an example holds only lines and filled areas");
        if (tag == "circle" || tag == "ellipse") fail(n, "<" + tag + "> is not supported: edges must be straight (draw a polygon)");
        if (tag != "g" && !shapes.count(tag)) fail(n, "<" + tag + "> is not supported");
        const Style own = styleOf(n, style);
        const Matrix ownCtm = transformOf(n, ctm);
        if (tag == "g")
            children(n, ownCtm, own);
        else
            shape(n, ownCtm, own);
    }

    double length(const xmlNode* n, const char* name) const {
        const auto v = attribute(n, name);
        if (!v) return 0;   // SVG's default for every geometry attribute read here
        if (const auto x = svg::parseLength(*v)) return *x;
        failIn(n, std::string(name) + " \"" + *v + "\" is not a number");
    }

    std::vector<svg::Subpath> outlinesOf(const xmlNode* n, const std::string& tag) const {
        if (tag == "line")
            return {{{{length(n, "x1"), length(n, "y1")}, {length(n, "x2"), length(n, "y2")}}, false}};
        if (tag == "rect") {
            for (const char* r : {"rx", "ry"})
                if (attribute(n, r) && length(n, r) != 0) failIn(n, "rounded corners (rx, ry) are not supported");
            const double x = length(n, "x"), y = length(n, "y"), w = length(n, "width"), h = length(n, "height");
            if (w < 0 || h < 0) failIn(n, "a negative width or height is not allowed");
            if (w == 0 || h == 0) return {};   // SVG does not render it
            return {{{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}}, true}};
        }
        const char* data = tag == "path" ? "d" : "points";
        const std::string text = attribute(n, data).value_or("");
        try {
            if (tag == "path") return svg::parsePathData(text);
            const std::vector<double> xy = svg::parseNumberList(text);
            if (xy.size() % 2 != 0) failIn(n, "points has an odd number of coordinates");
            svg::Subpath s;
            for (std::size_t i = 0; i < xy.size(); i += 2) s.points.push_back({xy[i], xy[i + 1]});
            s.closed = tag == "polygon";
            return {s};
        } catch (const SyntaxError& e) {
            failIn(n, std::string(data) + ": " + e.message);
        }
    }

    static int indexOf(std::vector<std::string>& list, const std::string& color) {
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i] == color) return static_cast<int>(i);
        list.push_back(color);
        return static_cast<int>(list.size() - 1);
    }

    void shape(const xmlNode* n, const Matrix& ctm, const Style& style) {
        const std::string tag = tagOf(n);
        svg::DrawnElement d;
        d.tag = tag;
        d.line = xmlGetLineNo(n);
        d.evenOdd = style.evenOdd;
        bool anyClosed = false;
        for (const svg::Subpath& s : outlinesOf(n, tag)) {
            if (s.points.empty()) continue;   // points="": nothing drawn
            svg::Outline o;
            for (const UserPoint& p : s.points) {
                const UserPoint q = ctm.apply(p);
                if (!std::isfinite(q.x) || !std::isfinite(q.y)) failIn(n, "a point is out of range after the transforms");
                o.points.push_back({q.x / kUserUnitsPerCell, 0.0 - q.y / kUserUnitsPerCell});   // 0.0 -: no -0
            }
            const double dx = o.points.back().x - o.points.front().x, dy = o.points.back().y - o.points.front().y;
            o.closed = s.closed || (o.points.size() > 2 && dx * dx + dy * dy < kTolerance * kTolerance);
            anyClosed = anyClosed || o.closed;
            d.outlines.push_back(std::move(o));
        }
        if (d.outlines.empty()) return;
        if (style.stroke) d.stroke = indexOf(input_.strokeColors, *style.stroke);
        if (style.fill && anyClosed) d.fill = indexOf(fills_, *style.fill);
        input_.elements.push_back(std::move(d));
    }

    // Labels by first appearance, leaving out those no edge uses.
    void renumber(ExampleShape& out) const {
        std::vector<int> brush(input_.strokeColors.size(), -1), area(fills_.size(), -1);
        for (const ExampleEdge& e : out.edges) {
            brush[static_cast<std::size_t>(e.brush)] = 0;
            for (int a : {e.leftArea, e.rightArea})
                if (a >= 0) area[static_cast<std::size_t>(a)] = 0;
        }
        for (std::size_t i = 0; i < brush.size(); ++i)
            if (brush[i] == 0) {
                brush[i] = static_cast<int>(out.brushes.size());
                out.brushes.push_back({"Line" + std::to_string(out.brushes.size()), input_.strokeColors[i], false, 0, 0});
            }
        for (std::size_t i = 0; i < area.size(); ++i)
            if (area[i] == 0) {
                area[i] = static_cast<int>(out.areas.size());
                out.areas.push_back({"Area" + std::to_string(out.areas.size()), fills_[i]});
            }
        for (ExampleEdge& e : out.edges) {
            e.brush = brush[static_cast<std::size_t>(e.brush)];
            if (e.leftArea >= 0) e.leftArea = area[static_cast<std::size_t>(e.leftArea)];
            if (e.rightArea >= 0) e.rightArea = area[static_cast<std::size_t>(e.rightArea)];
        }
    }

    const std::string& path_;
    svg::PlanarInput input_;
    std::vector<std::string> fills_;
};

}  // namespace

ExampleShape readExampleSvg(const std::string& text, const std::string& path) {
    if (text.size() > static_cast<std::size_t>(INT_MAX)) throw InputError{path + ": the file is too large"};
    const std::unique_ptr<xmlParserCtxt, XmlContextFree> context(xmlNewParserCtxt());
    if (!context) throw std::bad_alloc();
    FirstError first;
    context->_private = &first;
    context->sax->serror = keepFirstError;
    // No entity loading from the network; BIG_LINES: true line numbers past 65535.
    const int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_BIG_LINES;
    const std::unique_ptr<xmlDoc, XmlDocFree> doc(
        xmlCtxtReadMemory(context.get(), text.data(), static_cast<int>(text.size()), nullptr, nullptr, options));
    if (!doc) {
        if (first.message.empty()) first.message = "unknown error";
        throw InputError{path + ":" + std::to_string(first.line) + ": not well-formed XML: " + first.message};
    }
    const xmlNode* root = xmlDocGetRootElement(doc.get());
    if (!root) throw InputError{path + ": the file has no root element"};
    return SvgReader(path).read(root);
}

}  // namespace g2d::infer
