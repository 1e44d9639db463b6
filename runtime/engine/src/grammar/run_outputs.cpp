#include "g2d/run_outputs.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "g2d/json_writer.hpp"
#include "g2d/obj_writer.hpp"

namespace g2d::rt {

void writeRunOutputs(GrammarRun& grammar, const RunOutputs& out) {
    const Graph& graph = grammar.graph();
    if (out.svg) {
        // Streamed: each item is made when written (twice: writeSvg), never all at once.
        const bool space3d = grammar.jsonSchema().space3d;
        std::optional<SolidFaces> solid;
        if (space3d) solid.emplace(graph);
        const ItemMaker drawn = [&](ElemClass cls, std::uint32_t id, DrawItem& it) {
            grammar.drawItem(cls, id, it);
            if (solid) projectItem(it, graph, out.view, *solid);
        };
        writeSvg(graph, drawn, grammar.svgDefs(), *out.svg, out.svgOptions);
    }
    if (out.json) {
        const std::vector<std::pair<std::string, Value>> meta = {{"grammar", out.grammarName},
                                                                 {"seed", static_cast<long long>(out.seed)},
                                                                 {"steps", out.steps},
                                                                 {"stopped", out.stopped}};
        writeJson(graph, grammar.jsonSchema(), meta, *out.json,
                  [&](ElemClass cls, std::uint32_t id, int a) { return grammar.attribute(cls, id, a); });
    }
    if (out.obj) {
        ObjOptions obj;
        obj.triangles = out.objTriangles;
        obj.mtl = out.mtl;
        obj.mtlName = out.mtlName;
        obj.faceItem = [&](ElemClass cls, std::uint32_t id, DrawItem& it) { grammar.drawItem(cls, id, it); };
        writeObj(graph, grammar.jsonSchema(), *out.obj, obj);
    }
}

const char* stopName(StopReason reason) { return reason == StopReason::Terminal ? "terminal" : "step_limit"; }

}  // namespace g2d::rt
