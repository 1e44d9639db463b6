#include "infer/rule_application.hpp"

namespace g2d::infer {

std::vector<HierarchyGraph> components(const LabelledExample& ex, const HierarchyGraph& g) {
    const std::size_t n = g.type.size();
    std::vector<int> component(n, -1), local(n, -1);
    std::vector<HierarchyGraph> out;
    for (std::size_t start = 0; start < n; ++start) {
        if (component[start] >= 0) continue;
        const int c = static_cast<int>(out.size());
        std::vector<int> members{static_cast<int>(start)};
        component[start] = c;
        for (std::size_t k = 0; k < members.size(); ++k)
            for (const Link& l : g.links[static_cast<std::size_t>(members[k])])
                if (l.vertex >= 0 && component[static_cast<std::size_t>(l.vertex)] < 0) {
                    component[static_cast<std::size_t>(l.vertex)] = c;
                    members.push_back(l.vertex);
                }
        HierarchyGraph h;
        for (std::size_t k = 0; k < members.size(); ++k) local[static_cast<std::size_t>(members[k])] = static_cast<int>(k);
        for (int v : members) {
            h.type.push_back(g.type[static_cast<std::size_t>(v)]);
            std::vector<Link> links = g.links[static_cast<std::size_t>(v)];
            for (Link& l : links)
                if (l.vertex >= 0) l.vertex = local[static_cast<std::size_t>(l.vertex)];
            h.links.push_back(std::move(links));
        }
        h.boundary = walkBoundary(ex, h);
        out.push_back(std::move(h));
    }
    return out;
}

std::vector<HierarchyGraph> applyDestructively(const LabelledExample& ex, const InferredGrammar& grammar, const InferredRule& rule,
                                               const HierarchyGraph& host, const std::vector<int>& image) {
    const HierarchyGraph& left = grammar.hierarchy[static_cast<std::size_t>(rule.left)].graph;
    // The host without the match: kept vertices renumbered.
    std::vector<char> cut(host.type.size(), 0);
    for (int v : image) cut[static_cast<std::size_t>(v)] = 1;
    HierarchyGraph out;
    std::vector<int> renumber(host.type.size(), -1);
    for (std::size_t v = 0; v < host.type.size(); ++v)
        if (!cut[v]) {
            renumber[v] = static_cast<int>(out.type.size());
            out.type.push_back(host.type[v]);
        }
    for (std::size_t v = 0; v < host.type.size(); ++v) {
        if (cut[v]) continue;
        std::vector<Link> links = host.links[v];
        for (Link& l : links)
            if (l.vertex >= 0) l = cut[static_cast<std::size_t>(l.vertex)] ? Link{} : Link{renumber[static_cast<std::size_t>(l.vertex)], l.slot};
        out.links.push_back(std::move(links));
    }
    // The interface: per entry of L's boundary, the host half-edge across from it (or none: open in the host too).
    std::vector<Link> interface;
    for (const BoundaryEntry& e : left.boundary) {
        const Link across = host.links[static_cast<std::size_t>(image[static_cast<std::size_t>(e.vertex)])][static_cast<std::size_t>(e.slot)];
        interface.push_back(across.vertex >= 0 ? Link{renumber[static_cast<std::size_t>(across.vertex)], across.slot} : Link{});
    }
    auto join = [&](Link a, Link b) {
        if (a.vertex >= 0) out.links[static_cast<std::size_t>(a.vertex)][static_cast<std::size_t>(a.slot)] = b;
        if (b.vertex >= 0) out.links[static_cast<std::size_t>(b.vertex)][static_cast<std::size_t>(b.slot)] = a;
    };
    for (const RulePiece& piece : rule.right) {
        const HierarchyGraph& p = grammar.hierarchy[static_cast<std::size_t>(piece.graph)].graph;
        if (p.isEdgeGraph()) {   // the two interface half-edges joined by one edge
            join(interface[static_cast<std::size_t>(piece.leftEntry[0])], interface[static_cast<std::size_t>(piece.leftEntry[1])]);
            continue;
        }
        const int base = static_cast<int>(out.type.size());
        for (std::size_t v = 0; v < p.type.size(); ++v) {
            out.type.push_back(p.type[v]);
            std::vector<Link> links = p.links[v];
            for (Link& l : links)
                if (l.vertex >= 0) l.vertex += base;
            out.links.push_back(std::move(links));
        }
        for (std::size_t q = 0; q < p.boundary.size(); ++q) {
            const Link mine{base + p.boundary[q].vertex, p.boundary[q].slot};
            const Link other = interface[static_cast<std::size_t>(piece.leftEntry[q])];
            if (other.vertex >= 0) join(mine, other);
        }
    }
    return components(ex, out);
}

}  // namespace g2d::infer
