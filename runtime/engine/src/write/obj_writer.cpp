#include "g2d/obj_writer.hpp"

#include <algorithm>
#include <map>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "g2d/edge_paths.hpp"
#include "g2d/export_style.hpp"
#include "g2d/face_triangles.hpp"
#include "g2d/ops.hpp"
#include "g2d/polygon_triangles.hpp"

namespace g2d::rt {

namespace {

// OBJ indices (1-based, in write order): nodes', then each bent edge's points.
struct ObjIndex {
    std::vector<std::uint32_t> node;   // by node id
    std::vector<std::uint32_t> bend;   // by edge id: its first bend point's
    std::uint32_t of(const PathPoint& p) const {
        return p.node != kNoId ? node[p.node] : bend[p.edge] + p.index;
    }
};

std::vector<NodeId> faceRing(const Graph& g, FaceId f) {
    std::vector<NodeId> ring;
    CornerId c = g.firstCorner(f);
    for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) ring.push_back(g.cornerNode(c));
    return ring;
}

// `v` or `v//n` (n = 0: the face has no normal).
void writeCorner(TextOut& out, std::uint32_t vertex, std::uint32_t normal) {
    out.write(' ');
    out.integer(vertex);
    if (normal == 0) return;
    out.write("//");
    out.integer(normal);
}

// A face with holes as the triangles that cover it (OBJ has no holes).
void writeTriangles(const Graph& g, FaceId f, const ObjIndex& index, std::uint32_t normal, TextOut& out) {
    std::vector<std::uint32_t> vertex;   // by point: its OBJ index
    std::vector<vec2> points;
    std::vector<int> outer;
    std::vector<std::vector<int>> holes;
    auto ring = [&](const std::vector<NodeId>& nodes, std::vector<int>& into) {
        forEachRingPoint(g, nodes, [&](const PathPoint& p) {
            vertex.push_back(index.of(p));
            points.push_back(p.node != kNoId ? g.pos(p.node) : g.edgeBend(p.edge)[p.index]);
            into.push_back(static_cast<int>(points.size()) - 1);
        });
    };
    ring(faceRing(g, f), outer);
    for (const std::vector<NodeId>& hole : g.faceHoles(f)) ring(hole, holes.emplace_back());
    for (const auto& t : triangulate(points, outer, holes)) {
        out.write('f');
        for (int k : t) writeCorner(out, vertex[static_cast<std::size_t>(k)], normal);
        out.write('\n');
    }
}

void writeVertex(TextOut& out, vec3 p, const char* tag = "v ") {
    out.write(tag);
    out.number(p.x);
    out.write(' ');
    out.number(p.y);
    out.write(' ');
    out.number(p.z);
    out.write('\n');
}

// An MTL material: Kd the colour, d its opacity (sRGB, as OBJ importers take Kd).
void writeMaterial(TextOut& mtl, const ExportMaterial& m) {
    mtl.write("newmtl ");
    mtl.write(m.name);
    mtl.write("\nKd ");
    mtl.number(m.colour.r);
    mtl.write(' ');
    mtl.number(m.colour.g);
    mtl.write(' ');
    mtl.number(m.colour.b);
    mtl.write("\nd ");
    mtl.number(m.colour.a);
    mtl.write("\nillum 1\n\n");
}

}  // namespace

void writeObj(const Graph& g, const JsonSchema& schema, TextOut& out, const ObjOptions& options) {
    out.write("# g2d: ");
    out.integer(static_cast<long long>(g.nodeCount()));
    out.write(" nodes, ");
    out.integer(static_cast<long long>(g.edgeCount()));
    out.write(" edges, ");
    out.integer(static_cast<long long>(g.faceCount()));
    out.write(" faces\n");
    const bool materials = options.mtl && options.faceItem;
    if (materials) {
        out.write("mtllib ");
        out.write(options.mtlName);
        out.write('\n');
    }
    // OBJ indices are 1-based in write order; node ids have gaps after deletions.
    ObjIndex index{std::vector<std::uint32_t>(g.nodeCapacity(), 0), {}};
    std::uint32_t next = 1;
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        const vec3 p = g.pos3(n);
        if (!isFinitePosition(p)) throw std::runtime_error("node " + std::to_string(n) + "'s position is not finite");
        writeVertex(out, p);
        index.node[n] = next++;
    }
    if (g.hasBends()) {
        index.bend.assign(g.edgeCapacity(), 0);
        for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
            if (!g.edgeAlive(e)) continue;
            index.bend[e] = next;
            for (const vec2& p : g.edgeBend(e)) writeVertex(out, {p.x, p.y, 0}), ++next;
        }
    }
    // Materials by name, in the order faces first use them (the MTL's order).
    std::map<std::string, bool> written;
    std::string current;
    DrawItem item;
    std::uint32_t normals = 0;
    for (std::size_t k = 0; k < g.kinds().size(); ++k) {
        if (g.kinds()[k].cls != ElemClass::Face) continue;
        const auto ofKind = g.facesOfKind(static_cast<int>(k));
        if (ofKind.empty()) continue;
        std::vector<FaceId> faces(ofKind.begin(), ofKind.end());
        std::sort(faces.begin(), faces.end());
        out.write("g ");
        out.write(schema.kindNames[k]);
        out.write('\n');
        current.clear();   // a group starts with its material
        for (FaceId f : faces) {
            if (materials) {
                options.faceItem(ElemClass::Face, f, item);
                const ExportMaterial m = faceMaterial(item);
                if (!written.count(m.name)) {
                    written[m.name] = true;
                    writeMaterial(*options.mtl, m);
                }
                if (m.name != current) {
                    out.write("usemtl ");
                    out.write(m.name);
                    out.write('\n');
                    current = m.name;
                }
            }
            if (options.triangles) {
                const FaceTriangles t = triangulateFace(g, f);
                if (t.problem != FaceShapeProblem::None)
                    throw ExportError(faceShapeMessage(g, f, schema.kindNames[k], t.problem));
                writeVertex(out, t.normal, "vn ");
                ++normals;
                for (const auto& tri : t.triangles) {
                    out.write('f');
                    for (std::uint32_t p : tri) writeCorner(out, index.of(t.points[p]), normals);
                    out.write('\n');
                }
                continue;
            }
            // Newell's normal, as the face's own facts give it; none for a face without area.
            const vec3 area = g.vectorArea(f);
            std::uint32_t normal = 0;
            if (length(area) > 0 && isFinitePosition(area)) {
                writeVertex(out, normalize(area), "vn ");
                normal = ++normals;
            }
            if (!g.faceHoles(f).empty()) {
                writeTriangles(g, f, index, normal, out);
                continue;
            }
            out.write('f');
            forEachRingPoint(g, faceRing(g, f), [&](const PathPoint& p) { writeCorner(out, index.of(p), normal); });
            out.write('\n');
        }
    }
    if (g.edgeCount() > 0) {
        out.write("g edges\n");
        for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
            if (!g.edgeAlive(e)) continue;
            out.write("l ");
            out.integer(index.node[g.source(e)]);
            for (std::size_t k = 0; k < g.edgeBend(e).size(); ++k) {
                out.write(' ');
                out.integer(index.bend[e] + static_cast<std::uint32_t>(k));
            }
            out.write(' ');
            out.integer(index.node[g.target(e)]);
            out.write('\n');
        }
    }
    out.flush();
    if (materials) options.mtl->flush();
}

std::string writeObj(const Graph& g, const JsonSchema& schema) {
    StringOut out;
    writeObj(g, schema, out, {});
    return std::move(out.text());
}

}  // namespace g2d::rt
