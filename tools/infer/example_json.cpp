#include "infer/example_json.hpp"

#include "infer/json_text.hpp"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace g2d::infer {
namespace {

using nlohmann::json;

// Walks the flat `data` array; every read says where it was, for messages.
class DataReader {
public:
    DataReader(const json& data, std::string path) : data_(data), path_(std::move(path)) {}

    [[noreturn]] void fail(std::size_t at, const std::string& what) const {
        throw InputError{path_ + ": data[" + std::to_string(at) + "]: " + what};
    }
    std::size_t at() const { return i_; }
    const std::string& path() const { return path_; }
    std::string where(std::size_t at) const { return "data[" + std::to_string(at) + "]"; }
    const json& next(const char* what) {
        if (i_ >= data_.size()) fail(i_, std::string("the array ends where ") + what + " should be");
        return data_[i_++];
    }
    long long integer(const char* what) {
        const json& v = next(what);
        if (!v.is_number_integer()) fail(i_ - 1, std::string("expected ") + what + " (an integer)");
        return v.get<long long>();
    }
    long long count(const char* what, long long max = 1'000'000) {
        const long long n = integer(what);
        if (n < 0 || n > max) fail(i_ - 1, std::string(what) + " " + std::to_string(n) + " is out of range");
        return n;
    }
    std::string string(const char* what) {
        const json& v = next(what);
        if (!v.is_string()) fail(i_ - 1, std::string("expected ") + what + " (a string)");
        return v.get<std::string>();
    }
    bool boolean(const char* what) {
        const json& v = next(what);
        if (!v.is_boolean()) fail(i_ - 1, std::string("expected ") + what + " (true or false)");
        return v.get<bool>();
    }
    double number(const char* what) {
        const json& v = next(what);
        if (!v.is_number()) fail(i_ - 1, std::string("expected ") + what + " (a number)");
        return v.get<double>();
    }
    bool done() const { return i_ == data_.size(); }

private:
    const json& data_;
    std::string path_;
    std::size_t i_ = 0;
};

// "1,2,3" -> numbers; "" -> none.
std::vector<double> numberList(DataReader& r, std::size_t at, const std::string& text) {
    std::vector<double> out;
    if (text.empty()) return out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
            r.fail(at, "\"" + item + "\" is not a number");
        out.push_back(v);
    }
    return out;
}

json parseEmbedded(DataReader& r, std::size_t at, const std::string& text) {
    return parseJsonText(text, r.path() + ": " + r.where(at) + ": the embedded JSON");
}

double fieldNumber(const json& o, const char* key, double fallback) {
    const auto it = o.find(key);
    return it != o.end() && it->is_number() ? it->get<double>() : fallback;
}
bool fieldBool(const json& o, const char* key) {
    const auto it = o.find(key);
    return it != o.end() && it->is_boolean() && it->get<bool>();
}
std::string fieldString(const json& o, const char* key) {
    const auto it = o.find(key);
    return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
}

struct Shape {
    std::size_t verticesAt = 0;   // where the vertex list is in `data`
    std::vector<Point> vertices;
    std::vector<ExampleEdge> edges;
};

void readBrushes(DataReader& r, int version, ExampleShape& out) {
    if (version < 2) {
        out.brushes.push_back({"Line", "", false, 0, 0});
        return;
    }
    const long long n = r.count("the edge label count", 10'000);
    for (long long b = 0; b < n; ++b) {
        EdgeBrush brush;
        brush.name = "Line" + std::to_string(b);
        if (version >= 5) {
            const std::size_t at = r.at();
            const json o = parseEmbedded(r, at, r.string("an edge label"));
            if (!o.is_object()) r.fail(at, "an edge label must be a JSON object");
            brush.rigid = fieldBool(o, "Rigid");
            brush.minLength = fieldNumber(o, "Min Length", 0);
            brush.maxLength = fieldNumber(o, "Max Length", 0);
            brush.color = fieldString(o, "color");
            if (fieldBool(o, "Rigid Tiled")) brush.unit = fieldNumber(o, "Tile Length", 0);
            brush.bend = fieldNumber(o, "Bend", brush.bend);
            if (brush.unit < 0) r.fail(at, "the edge label's Tile Length must be positive");
            if (brush.minLength < 0 || brush.maxLength < brush.minLength)
                r.fail(at, "the edge label's length range is empty");
        } else {
            // Rigid, Classified by angle, Bidirectional Edges, Synthetic, [Grounded,] Bend, color, borderColor
            brush.rigid = r.boolean("the label's Rigid");
            r.boolean("the label's Classified by angle");
            r.boolean("the label's Bidirectional Edges");
            r.boolean("the label's Synthetic");
            if (version >= 4) r.boolean("the label's Grounded");
            brush.bend = r.number("the label's Bend");
            brush.color = r.string("the label's colour");
            r.string("the label's border colour");
        }
        out.brushes.push_back(brush);
    }
    if (out.brushes.empty()) out.brushes.push_back({"Line", "", false, 0, 0});
}

void readAreas(DataReader& r, int version, ExampleShape& out) {
    if (version < 3) return;
    const long long n = r.count("the area label count", 10'000);
    for (long long a = 0; a < n; ++a) {
        AreaLabel area;
        area.name = "Area" + std::to_string(a);
        if (version >= 5) {
            const std::size_t at = r.at();
            const json o = parseEmbedded(r, at, r.string("an area label"));
            if (!o.is_object()) r.fail(at, "an area label must be a JSON object");
            area.color = fieldString(o, "color");
        } else {
            area.color = r.string("the area's colour");
            r.string("the area's border colour");
        }
        out.areas.push_back(area);
    }
}

std::vector<Point> readVertices(DataReader& r, int version) {
    const std::size_t at = r.at();
    const std::string text = r.string("a shape's vertices");
    std::vector<Point> points;
    if (version >= 5) {
        const json list = parseEmbedded(r, at, text);
        if (!list.is_array()) r.fail(at, "a shape's vertices must be a JSON list");
        for (const json& p : list) {
            if (!p.is_object() || !p.contains("x") || !p.contains("y") || !p["x"].is_number() || !p["y"].is_number())
                r.fail(at, "a vertex must be an object with numbers x and y");
            points.push_back({p["x"].get<double>(), p["y"].get<double>()});
        }
        return points;
    }
    const std::vector<double> xy = numberList(r, at, text);
    if (xy.size() % 2 != 0) r.fail(at, "the vertex coordinates do not come in pairs");
    for (std::size_t i = 0; i < xy.size(); i += 2) points.push_back({xy[i], xy[i + 1]});
    return points;
}

Shape readShape(DataReader& r, int version, const ExampleShape& labels) {
    Shape s;
    s.verticesAt = r.at();
    s.vertices = readVertices(r, version);
    r.string("a shape's control points");
    const std::size_t edgesAt = r.at();
    const std::vector<double> ends = numberList(r, edgesAt, r.string("a shape's edges"));
    if (ends.size() % 4 != 0) r.fail(edgesAt, "a shape's edges must be 4 integers each");
    for (std::size_t i = 0; i < ends.size(); i += 4) {
        auto isVertex = [&](double v) { return v >= 0 && v < static_cast<double>(s.vertices.size()) && v == std::floor(v); };
        if (!isVertex(ends[i]) || !isVertex(ends[i + 1]))
            r.fail(edgesAt, "edge " + std::to_string(i / 4) + " names a vertex that does not exist");
        ExampleEdge e;
        e.from = static_cast<int>(ends[i]);
        e.to = static_cast<int>(ends[i + 1]);
        if (e.from == e.to) r.fail(edgesAt, "edge " + std::to_string(i / 4) + " starts and ends at one vertex");
        e.where = r.where(edgesAt) + ", edge " + std::to_string(i / 4);
        s.edges.push_back(e);
    }
    if (version >= 2) {
        const std::size_t at = r.at();
        const std::vector<double> brush = numberList(r, at, r.string("a shape's edge labels"));
        if (brush.size() != s.edges.size()) r.fail(at, "there must be one edge label per edge");
        for (std::size_t i = 0; i < brush.size(); ++i) {
            if (brush[i] < 0 || brush[i] >= static_cast<double>(labels.brushes.size()) || brush[i] != std::floor(brush[i]))
                r.fail(at, "edge " + std::to_string(i) + " has no edge label " + std::to_string(brush[i]));
            s.edges[i].brush = static_cast<int>(brush[i]);
        }
    }
    if (version >= 3) {
        const std::size_t at = r.at();
        const std::vector<double> areas = numberList(r, at, r.string("a shape's area labels"));
        if (areas.size() != 2 * s.edges.size()) r.fail(at, "there must be two area labels per edge");
        for (std::size_t i = 0; i < areas.size(); ++i) {
            const double a = areas[i];
            if (a < -1 || a >= static_cast<double>(labels.areas.size()) || a != std::floor(a))
                r.fail(at, "edge " + std::to_string(i / 2) + " has no area label " + std::to_string(a));
            (i % 2 == 0 ? s.edges[i / 2].leftArea : s.edges[i / 2].rightArea) = static_cast<int>(a);
        }
    }
    return s;
}

// Places the instances, merging vertices closer than one pixel (as the
// author's app does), and turns pixels (y down) into grid units (y up).
void place(DataReader& r, int version, const std::vector<Shape>& shapes, double unit, ExampleShape& out) {
    const long long n = r.count("the instance count");
    std::map<std::pair<int, int>, int> edgeOf;
    for (long long k = 0; k < n; ++k) {
        if (version >= 3) r.integer("an instance's group");
        const std::size_t at = r.at();
        const long long shape = r.integer("an instance's shape");
        if (shape < 0 || shape >= static_cast<long long>(shapes.size())) r.fail(at, "there is no shape " + std::to_string(shape));
        const double dx = r.number("an instance's x offset");
        const double dy = r.number("an instance's y offset");
        r.boolean("an instance's rigid flag");
        const Shape& s = shapes[static_cast<std::size_t>(shape)];
        std::vector<int> index;
        for (std::size_t v = 0; v < s.vertices.size(); ++v) {
            const Point p{(s.vertices[v].x + dx) / unit, -(s.vertices[v].y + dy) / unit};
            int found = -1;
            for (std::size_t u = 0; u < out.vertices.size() && found < 0; ++u) {
                const double ddx = (out.vertices[u].x - p.x) * unit, ddy = (out.vertices[u].y - p.y) * unit;
                if (ddx * ddx + ddy * ddy < 1) found = static_cast<int>(u);
            }
            if (found < 0) {
                found = static_cast<int>(out.vertices.size());
                out.vertices.push_back(p);
                out.vertexWhere.push_back(r.where(s.verticesAt) + ", vertex " + std::to_string(v));
            }
            index.push_back(found);
        }
        for (ExampleEdge e : s.edges) {
            e.from = index[static_cast<std::size_t>(e.from)];
            e.to = index[static_cast<std::size_t>(e.to)];
            if (e.from == e.to) throw InputError{r.path() + ": " + e.where + " is shorter than a pixel"};
            const auto key = std::minmax(e.from, e.to);
            if (edgeOf.count(key)) continue;   // an instance drawn over another: its edges are there already
            edgeOf[key] = static_cast<int>(out.edges.size());
            out.edges.push_back(e);
        }
    }
}

}  // namespace

ExampleShape readExampleJson(const std::string& text, const std::string& path) {
    const json doc = parseJsonText(text, path);
    ExampleShape out;
    out.source = path;
    double unit = 40;   // the app's Major Grid Spacing: lengths and the canvas are in these cells
    const json* data = &doc;
    if (doc.is_object()) {
        if (!doc.contains("data")) throw InputError{path + ": an example object needs a \"data\" array"};
        data = &doc["data"];
        out.name = doc.contains("name") && doc["name"].is_string() ? doc["name"].get<std::string>() : "";
        if (doc.contains("settings") && doc["settings"].is_string()) {
            const json settings = parseJsonText(doc["settings"].get<std::string>(), path + ": \"settings\"");
            unit = fieldNumber(settings, "Major Grid Spacing", unit);
            if (!(unit > 0)) throw InputError{path + ": \"settings\": Major Grid Spacing must be positive"};
            const auto ext = settings.find("Extents");
            if (ext != settings.end() && ext->is_array() && ext->size() >= 2 && (*ext)[0].is_number() && (*ext)[1].is_number()) {
                out.canvasWidth = (*ext)[0].get<double>();
                out.canvasHeight = (*ext)[1].get<double>();
            }
        }
    }
    if (!data->is_array()) throw InputError{path + ": the example must be the app's data array"};
    DataReader r(*data, path);
    const long long version = r.integer("the format version");
    if (version < 1 || version > 5) r.fail(0, "format version " + std::to_string(version) + " is not 1 to 5");
    const int v = static_cast<int>(version);
    readBrushes(r, v, out);
    readAreas(r, v, out);
    const long long shapeCount = r.count("the shape count");
    std::vector<Shape> shapes;
    for (long long s = 0; s < shapeCount; ++s) shapes.push_back(readShape(r, v, out));
    place(r, v, shapes, unit, out);
    if (!r.done()) r.fail(r.at(), "unexpected data after the last instance");
    if (out.edges.empty()) throw InputError{path + ": the example has no edges"};
    return out;
}

}  // namespace g2d::infer
