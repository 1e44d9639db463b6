// The --view page: the model as JSON inside the page, read by the embedded
// script (web/view/src/view.js documents the JSON's shape).
#include "g2d/view_page.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "g2d/face_triangles.hpp"
#include "g2d/json_writer.hpp"
#include "g2d/text_out.hpp"
#include "g2d/view_script.hpp"

namespace g2d::rt {

namespace {

// A visible colour: absent or "none" is not one.
bool painted(const std::string& css) { return !css.empty() && css != "none"; }

// Items by class and id (drawItems lists every live element once).
std::vector<const DrawItem*> itemsById(const std::vector<DrawItem>& items, ElemClass cls, std::size_t capacity) {
    std::vector<const DrawItem*> out(capacity, nullptr);
    for (const auto& it : items)
        if (it.cls == cls && it.id < capacity) out[it.id] = &it;
    return out;
}

double modelDiagonal(const Graph& g) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const vec3 p = g.pos3(n);
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    }
    if (lo[0] > hi[0]) return 0;
    return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// Inside <script>, "<" could end the element; JSON strings may spell it \u003c.
std::string scriptSafe(std::string json) {
    std::string out;
    out.reserve(json.size());
    for (char c : json) {
        if (c == '<') out.append("\\u003c");
        else out.push_back(c);
    }
    return out;
}

// Colours once each, in order of first use; elements refer to them by index.
class Palette {
public:
    long index(const std::string& css) {
        if (!painted(css)) return -1;
        auto [at, added] = indices_.try_emplace(css, static_cast<long>(names_.size()));
        if (added) names_.push_back(css);
        return at->second;
    }
    std::string json() const {
        std::string out = "[";
        for (std::size_t i = 0; i < names_.size(); ++i) out += (i ? "," : "") + jsonString(names_[i]);
        return out + "]";
    }

private:
    std::map<std::string, long> indices_;
    std::vector<std::string> names_;
};

}  // namespace

std::string viewModelJson(const ViewModel& m) {
    // Written straight into one buffer: a model of 20,000 elements took 7 ms as strings joined.
    Palette colors;
    StringOut out;
    auto number = [&out](double x) {
        if (!std::isfinite(x)) throw std::runtime_error("the model has a non-finite number (" + formatNumber(x) + ")");
        out.number(x);
    };
    auto list = [&out](const auto& items, const auto& write) {
        bool first = true;
        for (const auto& item : items) {
            out.write(first ? "\n[" : ",\n[");
            first = false;
            write(item);
            out.write(']');
        }
    };
    out.write("{\"title\":");
    out.write(jsonString(m.title));
    if (m.home) {
        out.write(",\n\"home\":[");
        number(m.home->x), out.write(','), number(m.home->y), out.write(','), number(m.home->z);
        out.write(']');
    }
    out.write(",\n\"counts\":{\"nodes\":"), out.integer(static_cast<long long>(m.graphNodes));
    out.write(",\"edges\":"), out.integer(static_cast<long long>(m.graphEdges));
    out.write(",\"faces\":"), out.integer(static_cast<long long>(m.graphFaces)), out.write('}');
    // The palette is written last in the text's order of fields, so it is collected first.
    for (const auto& n : m.nodes) colors.index(n.color);
    for (const auto& e : m.edges) colors.index(e.color);
    for (const auto& f : m.faces) colors.index(f.color);
    out.write(",\n\"colors\":"), out.write(colors.json());
    out.write(",\n\"nodes\":[");
    list(m.nodes, [&](const auto& n) {
        number(n.pos[0]), out.write(','), number(n.pos[1]), out.write(','), number(n.pos[2]), out.write(',');
        number(n.radius), out.write(','), out.integer(colors.index(n.color));
    });
    out.write("],\n\"edges\":[");
    list(m.edges, [&](const auto& e) {
        out.integer(static_cast<long long>(e.a)), out.write(','), out.integer(static_cast<long long>(e.b)), out.write(',');
        out.integer(colors.index(e.color)), out.write(','), number(e.radius);
    });
    out.write("],\n\"faces\":[");
    list(m.faces, [&](const auto& f) {
        out.integer(static_cast<long long>(f.id)), out.write(','), out.integer(colors.index(f.color)), out.write(",[");
        for (std::size_t i = 0; i < f.points.size(); ++i) {
            if (i) out.write(',');
            number(f.points[i][0]), out.write(','), number(f.points[i][1]), out.write(','), number(f.points[i][2]);
        }
        out.write("],[");
        for (std::size_t i = 0; i < f.triangles.size(); ++i) {
            if (i) out.write(',');
            out.integer(static_cast<long long>(f.triangles[i][0])), out.write(',');
            out.integer(static_cast<long long>(f.triangles[i][1])), out.write(',');
            out.integer(static_cast<long long>(f.triangles[i][2]));
        }
        out.write(']');
    });
    out.write("],\n\"faceAlphas\":[");
    for (std::size_t i = 0; i < m.faces.size(); ++i) {
        if (i) out.write(',');
        number(m.faces[i].opacity);
    }
    out.write("]}");
    return std::move(out.text());
}

namespace {

std::string counted(std::size_t n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

// The graph's count, and how many are drawn when not all are.
std::string counted(std::size_t all, std::size_t drawn, const std::string& noun) {
    return counted(all, noun) + (drawn < all ? " (" + std::to_string(drawn) + " drawn)" : "");
}

const char* const kStyle = R"CSS(
html, body { margin: 0; height: 100%; overflow: hidden; background: #fff; }
canvas { display: block; }
#legend { position: absolute; top: 8px; left: 8px; padding: 6px 10px; max-width: 40em;
  font: 13px system-ui, sans-serif; color: #222; background: rgba(255, 255, 255, 0.85);
  border: 1px solid #ddd; border-radius: 4px; }
#legend small { display: block; color: #666; margin-top: 2px; }
#status { color: #a33; }
#toggles, #views { display: inline-block; margin: 4px 8px 0 0; white-space: nowrap; }
#toggles label { margin-right: 6px; }
#views button { font: 12px system-ui, sans-serif; padding: 1px 6px; }
)CSS";

}  // namespace

ViewModel viewModelOf(const Graph& g, const std::vector<DrawItem>& items, const std::string& title,
                      const std::vector<std::string>& kindNames) {
    ViewModel m;
    m.title = title;
    m.graphNodes = g.nodeCount();
    m.graphEdges = g.edgeCount();
    m.graphFaces = g.faceCount();
    const double diagonal = modelDiagonal(g);
    const double defaultRadius = diagonal > 0 ? 0.006 * diagonal : 0.05;
    const auto nodeItems = itemsById(items, ElemClass::Node, g.nodeCapacity());
    std::vector<std::uint32_t> index(g.nodeCapacity(), 0);
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        index[n] = static_cast<std::uint32_t>(m.nodes.size());
        ViewNode v;
        const vec3 p = g.pos3(n);
        v.pos = {p.x, p.y, p.z};
        const DrawItem* it = nodeItems[n];
        const std::string tag = it ? styleText(*it, "tag", "circle") : "none";
        if (tag != "none") {
            // As the SVG paints a circle: `fill` (default none), else `stroke` (default black).
            const std::string fill = styleText(*it, "fill", "none");
            v.color = painted(fill) ? fill : styleText(*it, "stroke", "black");
            // `r` is a circle's (SVG draws a node tagged "line" as one too); other tags get the default.
            v.radius = tag == "circle" || tag == "line" ? styleNumber(*it, "r", defaultRadius) : defaultRadius;
        }
        if (!painted(v.color) || !(v.radius > 0)) {
            v.radius = 0;
            v.color.clear();
        }
        m.nodes.push_back(std::move(v));
    }
    const auto edgeItems = itemsById(items, ElemClass::Edge, g.edgeCapacity());
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        const DrawItem* it = g.edgeAlive(e) ? edgeItems[e] : nullptr;
        if (!it || styleText(*it, "tag", "line") == "none") continue;
        const std::string stroke = styleText(*it, "stroke", "black");
        if (painted(stroke))
            m.edges.push_back({index[g.source(e)], index[g.target(e)], stroke, (g.radius(g.source(e)) + g.radius(g.target(e))) / 2});
    }
    const auto faceItems = itemsById(items, ElemClass::Face, g.faceCapacity());
    for (FaceId f = 0; f < g.faceCapacity(); ++f) {
        const DrawItem* it = g.faceAlive(f) ? faceItems[f] : nullptr;
        if (!it || styleText(*it, "tag", "polygon") == "none") continue;
        ViewFace v;
        v.color = styleText(*it, "fill", "#d9d9d9");
        v.opacity = std::clamp(styleNumber(*it, "fill_opacity", 1.0), 0.0, 1.0);
        if (!painted(v.color) || v.opacity == 0) continue;
        const FaceTriangles t = triangulateFace(g, f);
        if (t.problem != FaceShapeProblem::None) {
            const auto kind = static_cast<std::size_t>(g.faceKind(f));
            throw std::runtime_error(faceShapeMessage(g, f, kind < kindNames.size() ? kindNames[kind] : "face", t.problem));
        }
        v.id = f;
        for (const vec3& p : t.positions) v.points.push_back({p.x, p.y, p.z});
        v.triangles = t.triangles;
        m.faces.push_back(std::move(v));
    }
    return m;
}

std::string writeViewPage(const ViewModel& m) {
    const std::string title = xmlEscape(m.title);
    std::size_t nodesDrawn = 0;
    for (const auto& n : m.nodes) nodesDrawn += n.radius > 0;
    const std::string counts = counted(m.graphNodes, nodesDrawn, "node") + ", " + counted(m.graphEdges, m.edges.size(), "edge") +
                               ", " + counted(m.graphFaces, m.faces.size(), "face");
    std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
                      title + " — g2d view</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
    out += "<div id=\"legend\"><strong>" + title + "</strong> — " + counts +
           "<small>Drag to turn, right-drag to pan, scroll to zoom; keys F, E, N, A, and R, 1, 2, 3, S, V "
           "as the buttons. Back sides are darker.</small>"
           "<span id=\"status\">This page needs JavaScript and WebGL.</span></div>\n";
    out += "<script id=\"g2d-model\" type=\"application/json\">" + scriptSafe(viewModelJson(m)) + "</script>\n";
    out += "<script>" + viewScript() + "</script>\n</body>\n</html>\n";
    return out;
}

}  // namespace g2d::rt
