#include "g2d/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace g2d::rt {

std::string xmlEscape(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

const Value* styleValue(const DrawItem& it, const char* prop) {
    for (const auto& p : it.props)
        if (p.prop == prop) return &p.value;
    return nullptr;
}

double styleNumber(const DrawItem& it, const char* prop, double fallback) {
    const Value* v = styleValue(it, prop);
    if (!v) return fallback;
    if (auto* d = std::get_if<double>(v)) return *d;
    if (auto* i = std::get_if<long long>(v)) return static_cast<double>(*i);
    return fallback;
}

std::string styleText(const DrawItem& it, const char* prop, const std::string& fallback) {
    const Value* v = styleValue(it, prop);
    return v ? toString(*v) : fallback;
}

namespace {

bool truthy(const DrawItem& it, const char* prop) {
    const Value* v = styleValue(it, prop);
    if (!v) return false;
    if (auto* b = std::get_if<bool>(v)) return *b;
    if (auto* s = std::get_if<std::string>(v)) return *s == "true";
    return styleNumber(it, prop, 0) != 0;
}

bool isSpecial(const std::string& p) {
    static const char* names[] = {"tag", "r", "width", "height", "rotate", "href", "text", "d", "points", "arrow", "z"};
    return std::any_of(std::begin(names), std::end(names), [&](const char* n) { return p == n; });
}

std::string attrName(std::string p) {
    std::replace(p.begin(), p.end(), '_', '-');
    return p;
}

// Every number a grammar makes is checked where it is made; this guards the
// file, so that nothing invalid is ever written.
std::string num(double x) {
    if (!std::isfinite(x)) throw std::runtime_error("the drawing has a non-finite number (" + formatNumber(x) + ")");
    return formatNumber(x);
}

// The frame is presentational: micro-unit steps (rounded outward) keep it tidy.
double down(double x) { return std::floor(x * 1e6 + 1e-6) / 1e6; }
double up(double x) { return std::ceil(x * 1e6 - 1e-6) / 1e6; }

// The pass-through attributes, with g2d's defaults for those not given.
std::string passThrough(const DrawItem& it, const std::vector<std::pair<const char*, const char*>>& defaults) {
    std::string out;
    for (const auto& [name, value] : defaults) {
        bool given = false;
        for (const auto& p : it.props) given = given || attrName(p.prop) == name;
        if (!given) out += std::string(" ") + name + "=\"" + value + "\"";
    }
    for (const auto& p : it.props) {
        if (isSpecial(p.prop)) continue;
        std::string value = toString(p.value);
        if (p.prop == "filter" && value.find('(') == std::string::npos && !value.empty()) value = "url(#" + value + ")";
        out += " " + attrName(p.prop) + "=\"" + xmlEscape(value) + "\"";
    }
    return out;
}

struct Box {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    void add(vec2 p, double pad) { add(p, pad, pad); }
    void add(vec2 p, double halfWidth, double halfHeight) {
        x0 = std::min(x0, p.x - halfWidth);
        y0 = std::min(y0, p.y - halfHeight);
        x1 = std::max(x1, p.x + halfWidth);
        y1 = std::max(y1, p.y + halfHeight);
    }
    // A w × h box centred at c, turned by `degrees`: its corners' extent.
    void addTurned(vec2 c, double w, double h, double degrees) {
        const double a = degrees * 3.141592653589793 / 180.0;
        const double cs = std::abs(std::cos(a)), sn = std::abs(std::sin(a));
        add(c, (w * cs + h * sn) / 2, (w * sn + h * cs) / 2);
    }
    bool empty() const { return x0 > x1; }
};

}  // namespace

std::string writeSvg(std::vector<DrawItem> items, const std::vector<std::string>& defs) {
    std::stable_sort(items.begin(), items.end(), [](const DrawItem& a, const DrawItem& b) {
        const double za = styleNumber(a, "z", 0), zb = styleNumber(b, "z", 0);
        if (za != zb) return za < zb;
        // Faces below edges below nodes.
        auto layer = [](ElemClass c) { return c == ElemClass::Face ? 0 : c == ElemClass::Edge ? 1 : 2; };
        if (a.cls != b.cls) return layer(a.cls) < layer(b.cls);
        // 3D: faces seen from the back first (on a closed surface they lie
        // behind those seen from the front, however big), then farther first.
        if (a.turnedAway != b.turnedAway) return a.turnedAway;
        if (a.depth != b.depth) return a.depth > b.depth;
        return a.id < b.id;
    });
    Box box;
    double maxStroke = 0;
    bool arrows = false;
    std::string body;
    for (const auto& it : items) {
        const bool isEdge = it.cls == ElemClass::Edge, isFace = it.cls == ElemClass::Face;
        const std::string tag = styleText(it, "tag", isEdge ? "line" : isFace ? "polygon" : "circle");
        if (tag == "none") continue;
        const double stroke = styleNumber(it, "stroke_width", isEdge ? 0.05 : isFace ? 0 : 0.02);
        maxStroke = std::max(maxStroke, stroke);
        const vec2 c = isEdge ? (it.a + it.b) * 0.5 : it.a;
        const double rotate = styleNumber(it, "rotate", 0);
        std::string rotation = rotate != 0 ? " transform=\"rotate(" + num(rotate) + " " + num(c.x) + " " + num(c.y) + ")\"" : "";
        if (tag == "polygon" && isFace) {
            std::string points;
            for (const vec2& p : it.corners) {
                box.add(p, 0);
                points += (points.empty() ? "" : " ") + num(p.x) + "," + num(p.y);
            }
            body += "<polygon points=\"" + points + "\"" + passThrough(it, {{"fill", "#d9d9d9"}, {"stroke", "none"}}) + "/>\n";
        } else if (tag == "line" && isEdge) {
            box.add(it.a, 0);
            box.add(it.b, 0);
            std::string marker;
            if (truthy(it, "arrow")) { marker = " marker-end=\"url(#g2d-arrow)\""; arrows = true; }
            body += "<line x1=\"" + num(it.a.x) + "\" y1=\"" + num(it.a.y) + "\" x2=\"" + num(it.b.x) + "\" y2=\"" +
                    num(it.b.y) + "\"" + passThrough(it, {{"stroke", "black"}, {"stroke-width", "0.05"}}) + marker +
                    "/>\n";
        } else if (tag == "circle" || (tag == "line" && !isEdge)) {
            const double r = styleNumber(it, "r", 0.1);
            box.add(c, r);
            body += "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\"" +
                    passThrough(it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.02"}}) + "/>\n";
        } else if (tag == "rect") {
            const double w = styleNumber(it, "width", 0.1), h = styleNumber(it, "height", 0.1);
            box.addTurned(c, w, h, rotate);
            body += "<rect x=\"" + num(c.x - w / 2) + "\" y=\"" + num(c.y - h / 2) + "\" width=\"" + num(w) +
                    "\" height=\"" + num(h) + "\"" + rotation + passThrough(it, {}) + "/>\n";
        } else if (tag == "path") {
            box.add(it.a, 0);
            if (isEdge) box.add(it.b, 0);
            body += "<path d=\"" + xmlEscape(styleText(it, "d", "")) + "\"" +
                    passThrough(it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.05"}}) + "/>\n";
        } else if (tag == "polyline") {
            box.add(it.a, 0);
            if (isEdge) box.add(it.b, 0);
            body += "<polyline points=\"" + xmlEscape(styleText(it, "points", "")) + "\"" +
                    passThrough(it, {{"fill", "none"}, {"stroke", "black"}, {"stroke-width", "0.05"}}) + "/>\n";
        } else if (tag == "image") {
            const double w = styleNumber(it, "width", 1), h = styleNumber(it, "height", 1);
            box.addTurned(c, w, h, rotate);
            // Images and text are flipped back upright inside the y-up group.
            body += "<image href=\"" + xmlEscape(styleText(it, "href", "")) + "\" x=\"" + num(-w / 2) + "\" y=\"" +
                    num(-h / 2) + "\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" transform=\"translate(" +
                    num(c.x) + " " + num(c.y) + ") rotate(" + num(rotate) + ") scale(1 -1)\"" + passThrough(it, {}) +
                    "/>\n";
        } else if (tag == "text") {
            box.add(c, 0);
            body += "<text transform=\"translate(" + num(c.x) + " " + num(c.y) + ") rotate(" + num(rotate) +
                    ") scale(1 -1)\"" + passThrough(it, {{"font-size", "0.5"}, {"text-anchor", "middle"}}) + ">" +
                    xmlEscape(styleText(it, "text", "")) + "</text>\n";
        }
    }
    double x0 = 0, y0 = 0, w = 1, h = 1;
    if (!box.empty()) {
        const double size = std::max(box.x1 - box.x0, box.y1 - box.y0);
        const double pad = maxStroke + 0.02 * size;
        x0 = down(box.x0 - pad);
        y0 = down(box.y0 - pad);
        w = up(std::max(box.x1 + pad - x0, 1e-3));
        h = up(std::max(box.y1 + pad - y0, 1e-3));
    }
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" + num(w) +
           "cm\" height=\"" + num(h) + "cm\" viewBox=\"" + num(x0) + " " + num(-(y0 + h)) + " " + num(w) + " " + num(h) +
           "\">\n";
    if (!defs.empty() || arrows) {
        out += "<defs>\n";
        if (arrows)
            out += "<marker id=\"g2d-arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"4\" "
                   "markerHeight=\"4\" orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\"/></marker>\n";
        for (const auto& d : defs) out += d + "\n";
        out += "</defs>\n";
    }
    out += "<g transform=\"scale(1 -1)\">\n" + body + "</g>\n</svg>\n";
    return out;
}

}  // namespace g2d::rt
