#include "g2d/svg_writer.hpp"

#include <algorithm>
#include <numeric>

#include "g2d/draw_order.hpp"
#include "g2d/svg_element.hpp"

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

const Value* styleValue(const DrawItem& it, std::string_view prop) {
    for (const auto& p : it.props)
        if (std::string_view(p.prop) == prop) return &p.value;
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

std::string writeSvg(std::vector<DrawItem> items, const std::vector<std::string>& defs, const SvgOptions& options) {
    std::vector<DrawKey> keys;
    keys.reserve(items.size());
    for (const auto& it : items) keys.push_back(drawKey(it));
    std::vector<std::size_t> order(items.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return drawnBefore(keys[a], keys[b]); });
    SvgFrame frame;
    for (const auto& it : items) measureItem(it, frame);
    StringOut out;
    writeSvgStart(frame, options.viewBox, defs, out);
    SvgBody body(out, options);
    for (std::size_t i : order) body.item(items[i]);
    body.finish();
    writeSvgEnd(out);
    return std::move(out.text());
}

void writeSvg(const Graph& g, const ItemMaker& make, const std::vector<std::string>& defs, TextOut& out,
              const SvgOptions& options) {
    // First pass: the frame (the document's start depends on every item) and the order.
    DrawItem it;
    SvgFrame frame;
    DrawOrder order;
    auto earlierKeys = [&](std::vector<DrawKey>& keys, std::size_t n) {
        DrawItem earlier;
        forEachLiveElement(g, [&](ElemClass cls, std::uint32_t id) {
            if (keys.size() == n) return false;
            make(cls, id, earlier);
            keys.push_back(drawKey(earlier));
            return true;
        });
    };
    // Elements that draw nothing (hidden nodes, as the thesis's grammars
    // have) are not made again: a bit each.
    std::vector<bool> written[3] = {std::vector<bool>(g.faceCapacity()), std::vector<bool>(g.edgeCapacity()),
                                    std::vector<bool>(g.nodeCapacity())};
    auto classIndex = [](ElemClass cls) { return cls == ElemClass::Face ? 0 : cls == ElemClass::Edge ? 1 : 2; };
    forEachLiveElement(g, [&](ElemClass cls, std::uint32_t id) {
        make(cls, id, it);
        written[classIndex(cls)][id] = measureItem(it, frame);
        order.add(drawKey(it), earlierKeys);
        return true;
    });
    // Second pass: each item made again and written.
    writeSvgStart(frame, options.viewBox, defs, out);
    SvgBody body(out, options);
    order.visit(g, [&](ElemClass cls, std::uint32_t id) {
        if (!written[classIndex(cls)][id]) return;
        make(cls, id, it);
        body.item(it);
    });
    body.finish();
    writeSvgEnd(out);
    out.flush();
}

}  // namespace g2d::rt
