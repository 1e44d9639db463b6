#include "g2d/draw_items.hpp"

namespace g2d::rt {

namespace {

Value printable(const Value& v, const std::vector<std::vector<std::string>>& enumValueNames) {
    if (const auto* e = std::get_if<EnumVal>(&v)) return enumValueNames[e->enumId][e->index];
    return v;
}

void resolve(DrawItem& item, int kind, StyleList own, const Graph& g, const std::vector<std::vector<std::string>>& names,
             const KindStyle& kindStyle) {
    kindStyle(item, kind);
    for (auto& p : item.props) p.value = printable(p.value, names);
    for (const auto& o : own) {
        const std::string& name = g.stylePropName(o.prop);
        bool replaced = false;
        for (auto& p : item.props)
            if (p.prop == name) {
                p.value = printable(o.value, names);
                replaced = true;
            }
        if (!replaced) item.props.push_back({name, printable(o.value, names)});
    }
}

}  // namespace

std::vector<DrawItem> drawItems(const Graph& g, const std::vector<std::vector<std::string>>& enumValueNames,
                                const KindStyle& kindStyle) {
    std::vector<DrawItem> items;
    for (FaceId f = 0; f < g.faceCapacity(); ++f) {
        if (!g.faceAlive(f)) continue;
        DrawItem item;
        item.cls = ElemClass::Face;
        item.id = f;
        CornerId c = g.firstCorner(f);
        for (int i = 0; i < g.cornerCount(f); ++i, c = g.nextCorner(c)) item.corners.push_back(g.pos(g.cornerNode(c)));
        item.a = item.b = g.centroid(f);
        resolve(item, g.faceKind(f), g.faceStyle(f), g, enumValueNames, kindStyle);
        items.push_back(std::move(item));
    }
    for (EdgeId e = 0; e < g.edgeCapacity(); ++e) {
        if (!g.edgeAlive(e)) continue;
        DrawItem item;
        item.cls = ElemClass::Edge;
        item.id = e;
        item.a = g.pos(g.source(e));
        item.b = g.pos(g.target(e));
        resolve(item, g.edgeKind(e), g.edgeStyle(e), g, enumValueNames, kindStyle);
        items.push_back(std::move(item));
    }
    for (NodeId n = 0; n < g.nodeCapacity(); ++n) {
        if (!g.nodeAlive(n)) continue;
        DrawItem item;
        item.id = n;
        item.a = g.pos(n);
        resolve(item, g.nodeKind(n), g.nodeStyle(n), g, enumValueNames, kindStyle);
        items.push_back(std::move(item));
    }
    return items;
}

}  // namespace g2d::rt
