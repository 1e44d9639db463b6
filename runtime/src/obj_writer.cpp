#include "g2d/obj_writer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "g2d/ops.hpp"
#include "g2d/polygon_triangles.hpp"

namespace g2d::rt {

namespace {

// A face with holes as the triangles that cover it (OBJ has no holes).
void writeTriangles(const Graph& g, FaceId f, const std::vector<std::uint32_t>& index, TextOut& out) {
    std::vector<NodeId> nodes;
    std::vector<vec2> points;
    std::vector<int> outer;
    std::vector<std::vector<int>> holes;
    auto corner = [&](NodeId n) {
        nodes.push_back(n);
        points.push_back(g.pos(n));
        return static_cast<int>(nodes.size()) - 1;
    };
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) outer.push_back(corner(g.cornerNode(c)));
    for (const std::vector<NodeId>& ring : g.faceHoles(f)) {
        holes.emplace_back();
        for (NodeId n : ring) holes.back().push_back(corner(n));
    }
    for (const auto& t : triangulate(points, outer, holes)) {
        out.write('f');
        for (int k : t) {
            out.write(' ');
            out.integer(index[nodes[static_cast<std::size_t>(k)]]);
        }
        out.write('\n');
    }
}

}  // namespace

void writeObj(const Graph& g, const JsonSchema& schema, TextOut& out) {
    out.write("# g2d: ");
    out.integer(static_cast<long long>(g.nodeCount()));
    out.write(" nodes, ");
    out.integer(static_cast<long long>(g.edgeCount()));
    out.write(" edges, ");
    out.integer(static_cast<long long>(g.faceCount()));
    out.write(" faces\n");
    // OBJ indices are 1-based in write order; node ids have gaps after deletions.
    std::vector<std::uint32_t> index(g.nodeCapacity(), 0);
    std::uint32_t next = 1;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const vec3 p = g.pos3(n);
        if (!isFinitePosition(p)) throw std::runtime_error("node " + std::to_string(n) + "'s position is not finite");
        out.write("v ");
        out.number(p.x);
        out.write(' ');
        out.number(p.y);
        out.write(' ');
        out.number(p.z);
        out.write('\n');
        index[n] = next++;
    }
    for (std::size_t k = 0; k < g.kinds().size(); ++k) {
        if (g.kinds()[k].cls != ElemClass::Face) continue;
        std::vector<FaceId> faces(g.facesOfKind(static_cast<int>(k)).begin(), g.facesOfKind(static_cast<int>(k)).end());
        if (faces.empty()) continue;
        std::sort(faces.begin(), faces.end());
        out.write("g ");
        out.write(schema.kindNames[k]);
        out.write('\n');
        for (FaceId f : faces) {
            if (!g.faceHoles(f).empty()) {
                writeTriangles(g, f, index, out);
                continue;
            }
            out.write('f');
            CornerId c = g.firstCorner(f);
            for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) {
                out.write(' ');
                out.integer(index[g.cornerNode(c)]);
            }
            out.write('\n');
        }
    }
    if (g.edgeCount() > 0) {
        out.write("g edges\n");
        for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
            if (!g.edgeAlive(e)) continue;
            out.write("l ");
            out.integer(index[g.source(e)]);
            out.write(' ');
            out.integer(index[g.target(e)]);
            out.write('\n');
        }
    }
    out.flush();
}

std::string writeObj(const Graph& g, const JsonSchema& schema) {
    StringOut out;
    writeObj(g, schema, out);
    return std::move(out.text());
}

}  // namespace g2d::rt
