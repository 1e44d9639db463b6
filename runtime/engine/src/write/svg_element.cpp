#include "g2d/svg_element.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "g2d/decorations.hpp"
#include "g2d/svg_extent.hpp"

namespace g2d::rt {

namespace {

// The path of one compact <path> is cut after this many lines, so that
// editors and viewers are not handed one element of gigabytes.
constexpr long kMaxRunSegments = 4096;

enum class Shape { None, Polygon, Line, Circle, Rect, Path, Polyline, Image, Text, Unknown };

Shape shapeOf(const DrawItem& it) {
    const bool isEdge = it.cls == ElemClass::Edge, isFace = it.cls == ElemClass::Face;
    const Value* v = styleValue(it, "tag");
    const std::string* s = v ? std::get_if<std::string>(v) : nullptr;
    const std::string other = v && !s ? toString(*v) : std::string();
    const std::string_view tag = !v ? (isEdge ? "line" : isFace ? "polygon" : "circle") : s ? std::string_view(*s) : other;
    if (tag == "none") return Shape::None;
    if (tag == "polygon" && isFace) return Shape::Polygon;
    if (tag == "line" && isEdge) return Shape::Line;
    if (tag == "circle" || tag == "line") return Shape::Circle;
    if (tag == "rect") return Shape::Rect;
    if (tag == "path") return Shape::Path;
    if (tag == "polyline") return Shape::Polyline;
    if (tag == "image") return Shape::Image;
    if (tag == "text") return Shape::Text;
    return Shape::Unknown;
}

vec2 centre(const DrawItem& it) { return it.cls == ElemClass::Edge ? (it.a + it.b) * 0.5 : it.a; }

bool truthy(const DrawItem& it, const char* prop) {
    const Value* v = styleValue(it, prop);
    if (!v) return false;
    if (auto* b = std::get_if<bool>(v)) return *b;
    if (auto* s = std::get_if<std::string>(v)) return *s == "true";
    return styleNumber(it, prop, 0) != 0;
}

// The properties with a meaning of their own (not attributes), by length:
// every item's every property is looked up here.
bool isSpecial(std::string_view p) {
    if (p.size() > 6 && p[0] == 'd' && isDecorProp(p)) return true;   // the decoration's (decorations.hpp)
    switch (p.size()) {
    case 1: return p == "r" || p == "d" || p == "z";
    case 3: return p == "tag";
    case 4: return p == "href" || p == "text";
    case 5: return p == "width" || p == "arrow";
    case 6: return p == "height" || p == "rotate" || p == "points";
    default: return false;
    }
}

// A property's attribute name is its name with `_` written `-`.
bool namesAttribute(std::string_view prop, std::string_view attr) {
    if (prop.size() != attr.size()) return false;
    for (std::size_t i = 0; i < attr.size(); ++i)
        if ((prop[i] == '_' ? '-' : prop[i]) != attr[i]) return false;
    return true;
}

void writeAttrName(TextOut& out, std::string_view prop) {
    if (prop.find('_') == std::string_view::npos) return out.write(prop);
    for (char c : prop) out.write(c == '_' ? '-' : c);
}

void writeEscaped(TextOut& out, std::string_view s) {
    std::size_t from = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const char* entity = nullptr;
        switch (s[i]) {
        case '&': entity = "&amp;"; break;
        case '<': entity = "&lt;"; break;
        case '>': entity = "&gt;"; break;
        case '"': entity = "&quot;"; break;
        case '\'': entity = "&apos;"; break;
        default: continue;
        }
        out.write(s.substr(from, i - from));
        out.write(entity);
        from = i + 1;
    }
    out.write(s.substr(from));
}

// Every number a grammar makes is checked where it is made; this guards the
// file, so that nothing invalid is ever written.
double checked(double x) {
    if (!std::isfinite(x)) throw std::runtime_error("the drawing has a non-finite number (" + formatNumber(x) + ")");
    return x;
}

void num(TextOut& out, double x) { out.number(checked(x)); }

struct Default {
    std::string_view name, value;
};

// The pass-through attributes, with g2d's defaults for those not given.
void passThrough(TextOut& out, const DrawItem& it, std::initializer_list<Default> defaults) {
    for (const auto& d : defaults) {
        bool given = false;
        for (const auto& p : it.props) given = given || namesAttribute(p.prop, d.name);
        if (given) continue;
        out.write(' ');
        out.write(d.name);
        out.write("=\"");
        out.write(d.value);
        out.write('"');
    }
    for (const auto& p : it.props) {
        if (isSpecial(p.prop)) continue;
        out.write(' ');
        writeAttrName(out, p.prop);
        out.write("=\"");
        if (const auto* d = std::get_if<double>(&p.value)) {
            out.number(*d);
        } else if (const auto* i = std::get_if<long long>(&p.value)) {
            out.integer(*i);
        } else {
            const std::string* s = std::get_if<std::string>(&p.value);
            const std::string text = s ? std::string() : toString(p.value);
            const std::string_view value = s ? std::string_view(*s) : std::string_view(text);
            const bool filterId = p.prop == "filter" && !value.empty() && value.find('(') == std::string_view::npos;
            if (filterId) out.write("url(#");
            writeEscaped(out, value);
            if (filterId) out.write(')');
        }
        out.write('"');
    }
}

// The frame is presentational: micro-unit steps (rounded outward) keep it tidy.
double down(double x) { return std::floor(x * 1e6 + 1e-6) / 1e6; }
double up(double x) { return std::ceil(x * 1e6 - 1e-6) / 1e6; }

}  // namespace

void SvgFrame::add(vec2 p, double halfWidth, double halfHeight) {
    x0 = std::min(x0, p.x - halfWidth);
    y0 = std::min(y0, p.y - halfHeight);
    x1 = std::max(x1, p.x + halfWidth);
    y1 = std::max(y1, p.y + halfHeight);
}

void SvgFrame::addTurned(vec2 c, double w, double h, double degrees) {
    const double a = degrees * 3.141592653589793 / 180.0;
    const double cs = std::abs(std::cos(a)), sn = std::abs(std::sin(a));
    add(c, (w * cs + h * sn) / 2, (w * sn + h * cs) / 2);
}

namespace {

void measureDecorations(const DrawItem& it, SvgFrame& frame) {
    for (const Placement& p : decorPlacements(it)) {
        const double r = styleNumber(it, "decor_r", std::min(p.width, p.height) / 2);
        if (decorShape(it) == DecorShape::Circle) frame.add(p.centre, r);
        else frame.addTurned(p.centre, p.width, p.height, p.degrees);
    }
}

}  // namespace

bool measureItem(const DrawItem& it, SvgFrame& frame) {
    const Shape shape = shapeOf(it);
    const bool decorated = decorShape(it) != DecorShape::None;
    if (decorated) measureDecorations(it, frame);
    if (shape == Shape::None) return decorated;
    const bool isEdge = it.cls == ElemClass::Edge, isFace = it.cls == ElemClass::Face;
    frame.maxStroke = std::max(frame.maxStroke, styleNumber(it, "stroke_width", isEdge ? 0.05 : isFace ? 0 : 0.02));
    const vec2 c = centre(it);
    switch (shape) {
    case Shape::Polygon:
        for (const vec2& p : it.corners) frame.add(p, 0);
        break;
    case Shape::Line:
        frame.add(it.a, 0);
        frame.add(it.b, 0);
        for (const vec2& p : it.bend) frame.add(p, 0);
        frame.arrows = frame.arrows || truthy(it, "arrow");
        break;
    case Shape::Circle: frame.add(c, styleNumber(it, "r", 0.1)); break;
    case Shape::Rect:
        frame.addTurned(c, styleNumber(it, "width", 0.1), styleNumber(it, "height", 0.1), styleNumber(it, "rotate", 0));
        break;
    case Shape::Path:
    case Shape::Polyline:
        frame.add(it.a, 0);
        if (isEdge) frame.add(it.b, 0);
        if (shape == Shape::Path) addPathExtent(styleText(it, "d", ""), frame);
        else addPointsExtent(styleText(it, "points", ""), frame);
        break;
    case Shape::Image:
        frame.addTurned(c, styleNumber(it, "width", 1), styleNumber(it, "height", 1), styleNumber(it, "rotate", 0));
        break;
    case Shape::Text:
        frame.add(c, 0);
        addTextExtent(c, styleText(it, "text", ""), styleNumber(it, "font_size", 0.5), styleText(it, "text_anchor", "middle"),
                      styleNumber(it, "rotate", 0), frame);
        break;
    case Shape::None:
    case Shape::Unknown: break;
    }
    return shape != Shape::Unknown || decorated;
}

void writeSvgStart(const SvgFrame& frame, const std::optional<ViewBox>& fixed, const std::vector<std::string>& defs,
                   TextOut& out) {
    double x0 = 0, y0 = 0, w = 1, h = 1;
    if (fixed) {   // as given: no margin, no rounding
        x0 = fixed->x0;
        y0 = fixed->y0;
        w = fixed->x1 - fixed->x0;
        h = fixed->y1 - fixed->y0;
    } else if (!frame.empty()) {
        const double size = std::max(frame.x1 - frame.x0, frame.y1 - frame.y0);
        const double pad = frame.maxStroke + 0.02 * size;
        x0 = down(frame.x0 - pad);
        y0 = down(frame.y0 - pad);
        w = up(std::max(frame.x1 + pad - x0, 1e-3));
        h = up(std::max(frame.y1 + pad - y0, 1e-3));
    }
    out.write("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    out.write("<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"");
    num(out, w);
    out.write("cm\" height=\"");
    num(out, h);
    out.write("cm\" viewBox=\"");
    num(out, x0);
    out.write(' ');
    num(out, fixed ? 0.0 - fixed->y1 : -(y0 + h));   // the top (y flips); y1 itself, as y0 + h may round
    out.write(' ');
    num(out, w);
    out.write(' ');
    num(out, h);
    out.write("\">\n");
    if (!defs.empty() || frame.arrows) {
        out.write("<defs>\n");
        if (frame.arrows)
            out.write("<marker id=\"g2d-arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"4\" "
                      "markerHeight=\"4\" orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\"/></marker>\n");
        for (const auto& d : defs) {
            out.write(d);
            out.write('\n');
        }
        out.write("</defs>\n");
    }
    out.write("<g transform=\"scale(1 -1)\">\n");
}

void writeSvgEnd(TextOut& out) { out.write("</g>\n</svg>\n"); }

SvgBody::SvgBody(TextOut& out, const SvgOptions& options) : out_(out), options_(options) {
    if (options_.precision) scale_ = std::pow(10.0, *options_.precision);
}

// A coordinate, rounded to --precision decimals when asked.
void SvgBody::coord(double x) {
    checked(x);
    out_.number(options_.precision ? std::round(x * scale_) / scale_ : x);
}

void SvgBody::point(vec2 p, char between) {
    coord(p.x);
    out_.write(between);
    coord(p.y);
}

// A face with holes: one path of its rings, the holes left unfilled by
// `evenodd` (and by `nonzero` too: they run the other way round).
void SvgBody::ringsPath(const DrawItem& it) {
    out_.write("<path d=\"");
    auto ring = [&](const std::vector<vec2>& corners) {
        for (std::size_t i = 0; i < corners.size(); ++i) {
            out_.write(i == 0 ? "M" : " L");
            point(corners[i], ',');
        }
        out_.write(" Z");
    };
    ring(it.corners);
    for (const std::vector<vec2>& hole : it.holes) {
        out_.write(' ');
        ring(hole);
    }
    out_.write('"');
    passThrough(out_, it, {{"fill", "#d9d9d9"}, {"stroke", "none"}, {"fill-rule", "evenodd"}});
    out_.write("/>\n");
}

void SvgBody::item(const DrawItem& it) {
    element(it);
    if (decorShape(it) == DecorShape::None) return;
    finish();
    decorations(it);
}

// Each placement of the item's decoration (decorations.hpp), after the item.
void SvgBody::decorations(const DrawItem& it) {
    DrawItem attrs;   // the placements' own attributes: decor_PROP as PROP
    for (const auto& p : it.props)
        if (isDecorProp(p.prop) && !isPlacementProp(p.prop)) attrs.props.push_back({p.prop.substr(6), p.value});
    const DecorShape shape = decorShape(it);
    const std::string href = shape == DecorShape::Image ? styleText(it, "decor_href", "") : "";
    for (const Placement& p : decorPlacements(it)) {
        if (shape == DecorShape::Circle) {
            out_.write("<circle cx=\"");
            coord(p.centre.x);
            out_.write("\" cy=\"");
            coord(p.centre.y);
            out_.write("\" r=\"");
            num(out_, styleNumber(it, "decor_r", std::min(p.width, p.height) / 2));
            out_.write('"');
            passThrough(out_, attrs, {});
            out_.write("/>\n");
            continue;
        }
        out_.write(shape == DecorShape::Image ? "<image href=\"" : "<rect");
        if (shape == DecorShape::Image) {
            writeEscaped(out_, options_.imageHref ? options_.imageHref(href) : href);
            out_.write('"');
        }
        out_.write(" x=\"");
        num(out_, -p.width / 2);
        out_.write("\" y=\"");
        num(out_, -p.height / 2);
        out_.write("\" width=\"");
        num(out_, p.width);
        out_.write("\" height=\"");
        num(out_, p.height);
        out_.write("\" transform=\"translate(");
        point(p.centre, ' ');
        out_.write(") rotate(");
        num(out_, p.degrees);
        out_.write(shape == DecorShape::Image ? ") scale(1 -1)\"" : ")\"");   // images upright in the y-up group
        passThrough(out_, attrs, {});
        out_.write("/>\n");
    }
}

void SvgBody::element(const DrawItem& it) {
    const Shape shape = shapeOf(it);
    if (shape == Shape::None || shape == Shape::Unknown) return;
    // A line with a fill would be filled as a path: it keeps its element.
    if (options_.compact && shape == Shape::Line && !truthy(it, "arrow") && !styleValue(it, "fill")) return continueRun(it);
    finish();
    TextOut& out = out_;
    const vec2 c = centre(it);
    switch (shape) {
    case Shape::Polygon: {
        if (!it.holes.empty()) {
            ringsPath(it);
            break;
        }
        out.write("<polygon points=\"");
        bool first = true;
        for (const vec2& p : it.corners) {
            if (!first) out.write(' ');
            first = false;
            point(p, ',');
        }
        out.write('"');
        passThrough(out, it, {{"fill", "#d9d9d9"}, {"stroke", "none"}});
        out.write("/>\n");
        break;
    }
    case Shape::Line:
        if (!it.bend.empty()) {
            out.write("<polyline points=\"");
            point(it.a, ',');
            for (const vec2& p : it.bend) {
                out.write(' ');
                point(p, ',');
            }
            out.write(' ');
            point(it.b, ',');
            out.write('"');
            passThrough(out, it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.05"}});
            if (truthy(it, "arrow")) out.write(" marker-end=\"url(#g2d-arrow)\"");
            out.write("/>\n");
            break;
        }
        out.write("<line x1=\"");
        coord(it.a.x);
        out.write("\" y1=\"");
        coord(it.a.y);
        out.write("\" x2=\"");
        coord(it.b.x);
        out.write("\" y2=\"");
        coord(it.b.y);
        out.write('"');
        passThrough(out, it, {{"stroke", "black"}, {"stroke-width", "0.05"}});
        if (truthy(it, "arrow")) out.write(" marker-end=\"url(#g2d-arrow)\"");
        out.write("/>\n");
        break;
    case Shape::Circle:
        out.write("<circle cx=\"");
        coord(c.x);
        out.write("\" cy=\"");
        coord(c.y);
        out.write("\" r=\"");
        num(out, styleNumber(it, "r", 0.1));
        out.write('"');
        passThrough(out, it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.02"}});
        out.write("/>\n");
        break;
    case Shape::Rect: {
        const double w = styleNumber(it, "width", 0.1), h = styleNumber(it, "height", 0.1), rotate = styleNumber(it, "rotate", 0);
        out.write("<rect x=\"");
        coord(c.x - w / 2);
        out.write("\" y=\"");
        coord(c.y - h / 2);
        out.write("\" width=\"");
        num(out, w);
        out.write("\" height=\"");
        num(out, h);
        out.write('"');
        if (rotate != 0) {
            out.write(" transform=\"rotate(");
            num(out, rotate);
            out.write(' ');
            point(c, ' ');
            out.write(")\"");
        }
        passThrough(out, it, {});
        out.write("/>\n");
        break;
    }
    case Shape::Path:
    case Shape::Polyline: {
        const bool path = shape == Shape::Path;
        out.write(path ? "<path d=\"" : "<polyline points=\"");
        writeEscaped(out, styleText(it, path ? "d" : "points", ""));
        out.write('"');
        passThrough(out, it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.05"}});
        out.write("/>\n");
        break;
    }
    case Shape::Image: {
        const double w = styleNumber(it, "width", 1), h = styleNumber(it, "height", 1);
        // Images and text are flipped back upright inside the y-up group.
        out.write("<image href=\"");
        const std::string href = styleText(it, "href", "");
        writeEscaped(out, options_.imageHref ? options_.imageHref(href) : href);
        out.write("\" x=\"");
        num(out, -w / 2);
        out.write("\" y=\"");
        num(out, -h / 2);
        out.write("\" width=\"");
        num(out, w);
        out.write("\" height=\"");
        num(out, h);
        out.write("\" transform=\"translate(");
        point(c, ' ');
        out.write(") rotate(");
        num(out, styleNumber(it, "rotate", 0));
        out.write(") scale(1 -1)\"");
        passThrough(out, it, {});
        out.write("/>\n");
        break;
    }
    case Shape::Text:
        out.write("<text transform=\"translate(");
        point(c, ' ');
        out.write(") rotate(");
        num(out, styleNumber(it, "rotate", 0));
        out.write(") scale(1 -1)\"");
        passThrough(out, it, {{"font-size", "0.5"}, {"text-anchor", "middle"}});
        out.write('>');
        writeEscaped(out, styleText(it, "text", ""));
        out.write("</text>\n");
        break;
    case Shape::None:
    case Shape::Unknown: break;
    }
}

// The compact form: a line joins the open <path> when it looks the same,
// continuing its last subpath when it starts where that ended.
void SvgBody::continueRun(const DrawItem& it) {
    std::string& attrs = attrs_.text();
    attrs.clear();
    passThrough(attrs_, it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.05"}});
    if (runSegments_ > 0 && (attrs_.text() != runAttrs_ || runSegments_ >= kMaxRunSegments)) finish();
    if (runSegments_ == 0) {
        runAttrs_ = attrs_.text();
        out_.write("<path d=\"M ");
        point(it.a, ' ');
        out_.write(" L ");
    } else if (it.a.x == runEnd_.x && it.a.y == runEnd_.y) {
        out_.write(' ');
    } else {
        out_.write(" M ");
        point(it.a, ' ');
        out_.write(" L ");
    }
    for (const vec2& p : it.bend) {
        point(p, ' ');
        out_.write(' ');
    }
    point(it.b, ' ');
    runEnd_ = it.b;
    ++runSegments_;
}

void SvgBody::finish() {
    if (runSegments_ == 0) return;
    out_.write('"');
    out_.write(runAttrs_);
    out_.write("/>\n");
    runSegments_ = 0;
}

}  // namespace g2d::rt
