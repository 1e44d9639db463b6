#include "sema/mirrored_face_lint.hpp"

#include <cstddef>
#include <map>
#include <set>
#include <vector>

namespace g2d::sema {

namespace {

using Kinds = std::vector<int>;   // corner kinds in order; -1: any (a wildcard)

// Whether some rotation of `face` (a face made) fits `pattern` corner by corner.
bool fitsRotated(const Kinds& pattern, const Kinds& face) {
    const std::size_t k = pattern.size();
    if (face.size() != k) return false;
    for (std::size_t r = 0; r < k; ++r) {
        bool fits = true;
        for (std::size_t i = 0; i < k && fits; ++i) {
            const int p = pattern[i], f = face[(i + r) % k];
            fits = p < 0 || f < 0 || p == f;
        }
        if (fits) return true;
    }
    return false;
}

}  // namespace

// Only the corner kinds are known statically, and only while faces keep the
// corners they are made with: kinds whose faces something else makes or
// reshapes (`insert`, `split`, merging, a loop's faces, `layout angles`' drawn
// faces) are left alone.
void warnMirroredFacePatterns(Globals& g) {
    const ir::Program& p = g.prog;
    if (p.mergeTolerance || p.angleLayout) return;
    std::set<int> unknown;   // face kinds whose faces' corner kinds are not all known
    std::map<int, std::vector<Kinds>> made;
    bool inserts = false;
    auto kindsOf = [](const std::vector<int>& corners, auto kindOf) {
        Kinds out;
        for (int c : corners) out.push_back(kindOf(static_cast<std::size_t>(c)));
        return out;
    };
    for (const auto& f : p.axiom.faces)
        made[f.kind].push_back(kindsOf(f.corners, [&](std::size_t i) { return p.axiom.nodes[i].kind; }));
    for (const auto& r : p.rules) {
        if (r.merge) return;
        for (const auto& d : r.daughters) {
            inserts = inserts || !d.inserts.empty();
            for (const auto& f : d.faces)
                made[f.kind].push_back(kindsOf(f.corners, [&](std::size_t i) { return d.nodes[i].kind; }));
            for (const auto& sp : d.splits) unknown.insert(r.faces[static_cast<std::size_t>(sp.motherFace)].kind);
            for (const auto& l : d.loops)
                for (const auto& f : l.faces) unknown.insert(f.kind);
        }
    }
    if (inserts) return;   // any face may grow a corner of any kind
    for (const auto& r : p.rules) {
        if (r.span.file != g.mainFile) continue;
        for (const auto& f : r.faces) {
            if (f.corners.empty() || unknown.count(f.kind)) continue;
            const Kinds pattern = kindsOf(f.corners, [&](std::size_t i) { return r.nodes[i].kind; });
            const Kinds mirrored(pattern.rbegin(), pattern.rend());
            bool forward = false, backward = false;
            for (const Kinds& m : made[f.kind]) {
                forward = forward || fitsRotated(pattern, m);
                backward = backward || fitsRotated(mirrored, m);
            }
            if (forward || !backward) continue;
            std::string reversed;
            for (auto it = f.corners.rbegin(); it != f.corners.rend(); ++it)
                reversed += (reversed.empty() ? "" : ", ") + r.nodes[static_cast<std::size_t>(*it)].name;
            g.diags.warning(f.span, "face pattern `" + f.name + "` lists its corners against the order of every `" + p.kinds[f.kind].name +
                                        "` face the grammar makes, and a face never matches its mirror image: write `" + f.name + ": " +
                                        p.kinds[f.kind].name + "(" + reversed + ")`");
        }
    }
}

}  // namespace g2d::sema
