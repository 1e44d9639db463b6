#include "g2d/draw_items.hpp"

#include "g2d/draw_order.hpp"
#include "g2d/edge_paths.hpp"

namespace g2d::rt {

namespace {

// Enum values print by their value's name; other values stay as they are.
void makePrintable(Value& v, const std::vector<std::vector<std::string>>& enumValueNames) {
    if (const auto* e = std::get_if<EnumVal>(&v)) v = enumValueNames[e->enumId][e->index];
}

void resolve(DrawItem& item, int kind, StyleList own, const Graph& g, const std::vector<std::vector<std::string>>& names,
             const KindStyle& kindStyle) {
    kindStyle(item, kind);
    for (auto& p : item.props) makePrintable(p.value, names);
    for (const auto& o : own) {
        const std::string& name = g.stylePropName(o.prop);
        bool replaced = false;
        for (auto& p : item.props)
            if (p.prop == name) {
                p.value = o.value;
                makePrintable(p.value, names);
                replaced = true;
            }
        if (!replaced) {
            item.props.push_back({name, o.value});
            makePrintable(item.props.back().value, names);
        }
    }
}

}  // namespace

void drawItem(const Graph& g, ElemClass cls, std::uint32_t id, const std::vector<std::vector<std::string>>& enumValueNames,
              const KindStyle& kindStyle, DrawItem& item) {
    item.cls = cls;
    item.id = id;
    item.corners.clear();
    item.holes.clear();
    item.bend.clear();
    item.props.clear();
    item.depth = 0;
    item.turnedAway = false;
    item.inDepth = false;
    if (cls == ElemClass::Face) {
        CornerId c = g.firstCorner(id);
        if (g.hasBends()) {   // the rings follow their edges' bends
            std::vector<NodeId> ring;
            for (int i = 0; i < g.cornerCount(id); ++i, c = g.nextCorner(c)) ring.push_back(g.cornerNode(c));
            item.corners = bentRing(g, ring);
            for (const std::vector<NodeId>& hole : g.faceHoles(id)) item.holes.push_back(bentRing(g, hole));
        } else {
            for (int i = 0; i < g.cornerCount(id); ++i, c = g.nextCorner(c)) item.corners.push_back(g.pos(g.cornerNode(c)));
            for (const std::vector<NodeId>& ring : g.faceHoles(id)) {
                item.holes.emplace_back();
                for (NodeId n : ring) item.holes.back().push_back(g.pos(n));
            }
        }
        item.a = item.b = g.centroid(id);
        resolve(item, g.faceKind(id), g.faceStyle(id), g, enumValueNames, kindStyle);
    } else if (cls == ElemClass::Edge) {
        item.a = g.pos(g.source(id));
        item.b = g.pos(g.target(id));
        const auto bend = g.edgeBend(id);
        item.bend.assign(bend.begin(), bend.end());
        resolve(item, g.edgeKind(id), g.edgeStyle(id), g, enumValueNames, kindStyle);
    } else {
        item.a = g.pos(id);
        item.b = {0, 0};
        resolve(item, g.nodeKind(id), g.nodeStyle(id), g, enumValueNames, kindStyle);
    }
}

std::vector<DrawItem> drawItems(const Graph& g, const std::vector<std::vector<std::string>>& enumValueNames,
                                const KindStyle& kindStyle) {
    return drawItems(g, [&](ElemClass cls, std::uint32_t id, DrawItem& item) {
        drawItem(g, cls, id, enumValueNames, kindStyle, item);
    });
}

std::vector<DrawItem> drawItems(const Graph& g, const ItemMaker& make) {
    std::vector<DrawItem> items;
    forEachLiveElement(g, [&](ElemClass cls, std::uint32_t id) {
        make(cls, id, items.emplace_back());
        return true;
    });
    return items;
}

}  // namespace g2d::rt
