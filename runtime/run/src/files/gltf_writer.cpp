#include "g2d/gltf_writer.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "g2d/export_style.hpp"
#include "g2d/face_triangles.hpp"

namespace g2d::rt {

namespace {

constexpr int kTubeSides = 8;

// glTF's y-up frame: the grammar's z is up.
std::array<float, 3> yUp(vec3 p) { return {static_cast<float>(p.x), static_cast<float>(p.z), static_cast<float>(-p.y)}; }

double linear(double srgb) { return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4); }

// One primitive's data, gathered per (mesh, material).
struct Part {
    std::vector<std::array<float, 3>> positions, normals;   // no normals: lines
    std::vector<std::uint32_t> indices;
    bool lines = false;
};

class GltfBuilder {
public:
    int material(const ExportMaterial& m) {
        const auto [it, added] = materials_.try_emplace(m.name, static_cast<int>(model_.materials.size()));
        if (added) {
            tinygltf::Material mat;
            mat.name = m.name;
            mat.pbrMetallicRoughness.baseColorFactor = {linear(m.colour.r), linear(m.colour.g), linear(m.colour.b), m.colour.a};
            mat.pbrMetallicRoughness.metallicFactor = 0;
            mat.pbrMetallicRoughness.roughnessFactor = 0.9;
            mat.alphaMode = m.colour.a < 1 ? "BLEND" : "OPAQUE";
            mat.doubleSided = true;   // open surfaces (a wall, a blade) show both sides, as in the SVG
            model_.materials.push_back(std::move(mat));
        }
        return it->second;
    }

    // A mesh and its node, named `name`, with a primitive per part (by material).
    void mesh(const std::string& name, const std::map<int, Part>& parts) {
        if (parts.empty()) return;
        tinygltf::Mesh mesh;
        mesh.name = name;
        for (const auto& [key, part] : parts) {
            tinygltf::Primitive p;
            p.material = key >= 0 ? key : -1 - key;
            p.mode = part.lines ? TINYGLTF_MODE_LINE : TINYGLTF_MODE_TRIANGLES;
            p.attributes["POSITION"] = vectors(part.positions, true);
            if (!part.normals.empty()) p.attributes["NORMAL"] = vectors(part.normals, false);
            p.indices = indices(part.indices);
            mesh.primitives.push_back(std::move(p));
        }
        tinygltf::Node node;
        node.name = name;
        node.mesh = static_cast<int>(model_.meshes.size());
        model_.meshes.push_back(std::move(mesh));
        model_.scenes[0].nodes.push_back(static_cast<int>(model_.nodes.size()));
        model_.nodes.push_back(std::move(node));
    }

    std::string glb() {
        if (bytes_.empty())
            model_.buffers.clear();   // nothing drawn: a buffer may not be empty
        else
            model_.buffers[0].data = std::move(bytes_);
        std::ostringstream out;
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToStream(&model_, out, false, true)) throw ExportError("the glTF writer failed");
        return out.str();
    }

    explicit GltfBuilder(const std::string& title) {
        model_.asset.version = "2.0";
        model_.asset.generator = "g2d";
        model_.scenes.emplace_back();
        model_.scenes[0].name = title;   // (a scene without nodes is then still an object)
        model_.defaultScene = 0;
        model_.buffers.emplace_back();
    }

private:
    int view(const void* data, std::size_t size, int target) {
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = bytes_.size();   // every element is 4 bytes: offsets stay aligned
        v.byteLength = size;
        v.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        bytes_.insert(bytes_.end(), p, p + size);
        model_.bufferViews.push_back(v);
        return static_cast<int>(model_.bufferViews.size()) - 1;
    }

    int vectors(const std::vector<std::array<float, 3>>& values, bool bounds) {
        tinygltf::Accessor a;
        a.bufferView = view(values.data(), values.size() * sizeof values[0], TINYGLTF_TARGET_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.type = TINYGLTF_TYPE_VEC3;
        a.count = values.size();
        if (bounds) {   // POSITION must have them, exactly the floats'
            a.minValues.assign(3, 0);
            a.maxValues.assign(3, 0);
            for (int k = 0; k < 3; ++k) {
                float lo = values[0][k], hi = values[0][k];
                for (const auto& v : values) lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
                a.minValues[k] = lo;
                a.maxValues[k] = hi;
            }
        }
        model_.accessors.push_back(std::move(a));
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    int indices(const std::vector<std::uint32_t>& values) {
        tinygltf::Accessor a;
        a.bufferView = view(values.data(), values.size() * sizeof values[0], TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.type = TINYGLTF_TYPE_SCALAR;
        a.count = values.size();
        model_.accessors.push_back(std::move(a));
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    tinygltf::Model model_;
    std::vector<unsigned char> bytes_;
    std::map<std::string, int> materials_;
};

bool hidden(const DrawItem& it, const char* defaultTag, const ExportMaterial& m) {
    return styleText(it, "tag", defaultTag) == "none" || !(m.colour.a > 0);
}

void addFace(const Graph& g, FaceId f, const std::string& kind, Part& part) {
    const FaceTriangles t = triangulateFace(g, f);
    if (t.problem != FaceShapeProblem::None) throw ExportError(faceShapeMessage(g, f, kind, t.problem));
    const auto first = static_cast<std::uint32_t>(part.positions.size());
    for (const vec3& p : t.positions) {
        part.positions.push_back(yUp(p));
        part.normals.push_back(yUp(t.normal));
    }
    for (const auto& tri : t.triangles)
        for (std::uint32_t k : tri) part.indices.push_back(first + k);
}

// An 8-sided open tube of radius r from a to b, its normals outward.
void addTube(vec3 a, vec3 b, double r, Part& part) {
    const vec3 d = normalize(b - a);
    const vec3 u = normalize(cross(d, std::abs(d.z) < 0.9 ? vec3{0, 0, 1} : vec3{1, 0, 0}));
    const vec3 v = cross(d, u);
    const auto first = static_cast<std::uint32_t>(part.positions.size());
    for (const vec3& end : {a, b})
        for (int k = 0; k < kTubeSides; ++k) {
            const double angle = 2 * std::numbers::pi * k / kTubeSides;
            const vec3 out = std::cos(angle) * u + std::sin(angle) * v;
            part.positions.push_back(yUp(end + r * out));
            part.normals.push_back(yUp(out));
        }
    for (std::uint32_t k = 0; k < kTubeSides; ++k) {
        const std::uint32_t a0 = first + k, a1 = first + (k + 1) % kTubeSides, b0 = a0 + kTubeSides, b1 = a1 + kTubeSides;
        part.indices.insert(part.indices.end(), {a0, a1, b1, a0, b1, b0});
    }
}

}  // namespace

std::string writeGltf(const Graph& g, const JsonSchema& schema, const ItemMaker& item, const std::string& title) {
    GltfBuilder gltf(title);
    DrawItem it;
    std::vector<std::vector<EdgeId>> edgesOfKind(g.kinds().size());
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e)
        if (g.edgeAlive(e)) edgesOfKind[static_cast<std::size_t>(g.edgeKind(e))].push_back(e);
    for (std::size_t k = 0; k < g.kinds().size(); ++k) {
        const ElemClass cls = g.kinds()[k].cls;
        // A primitive has one material and one mode: tubes by material, lines
        // by -1 - material.
        std::map<int, Part> parts;
        if (cls == ElemClass::Face) {
            std::vector<FaceId> faces(g.facesOfKind(static_cast<int>(k)).begin(), g.facesOfKind(static_cast<int>(k)).end());
            std::sort(faces.begin(), faces.end());
            for (FaceId f : faces) {
                item(cls, f, it);
                const ExportMaterial m = faceMaterial(it);
                if (!hidden(it, "polygon", m)) addFace(g, f, schema.kindNames[k], parts[gltf.material(m)]);
            }
        } else if (cls == ElemClass::Edge) {
            for (EdgeId e : edgesOfKind[k]) {
                item(cls, e, it);
                const ExportMaterial m = edgeMaterial(it);
                if (hidden(it, "line", m)) continue;
                const vec3 a = g.pos3(g.source(e)), b = g.pos3(g.target(e));
                const double r = (g.radius(g.source(e)) + g.radius(g.target(e))) / 2;
                const int material = gltf.material(m);
                if (r > 0 && length(b - a) > 0) {
                    addTube(a, b, r, parts[material]);
                    continue;
                }
                Part& lines = parts[-1 - material];
                lines.lines = true;
                const auto first = static_cast<std::uint32_t>(lines.positions.size());
                lines.positions.push_back(yUp(a));
                lines.positions.push_back(yUp(b));
                lines.indices.insert(lines.indices.end(), {first, first + 1});
            }
        }
        gltf.mesh(schema.kindNames[k], parts);
    }
    return gltf.glb();
}

}  // namespace g2d::rt
