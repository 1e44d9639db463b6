#include "brute_force_matcher.hpp"

#include <algorithm>

namespace g2d::test::brute {

const char* kindName(int kind) { return kind == 0 ? "A" : kind == 1 ? "B" : "*"; }

std::string edgeText(const std::string& a, int kind, const std::string& b) {
    return a + (kind == 0 ? " -[E]-> " : " -[U]- ") + b;
}

bool edgeFits(const Edge& h, int kind, int src, int dst) {
    if (h.kind != kind) return false;
    if (kind == 0) return h.src == src && h.dst == dst;
    return (h.src == src && h.dst == dst) || (h.src == dst && h.dst == src);
}

namespace {

long degree(const std::vector<Edge>& edges, int node) {
    return std::count_if(edges.begin(), edges.end(), [&](const Edge& e) { return e.src == node || e.dst == node; });
}

}  // namespace

Matches matches(const Graph& host, const Graph& pattern, const Options& options) {
    Matches out;
    const int hn = static_cast<int>(host.kinds.size()), pn = static_cast<int>(pattern.kinds.size());
    std::vector<int> nodes(static_cast<std::size_t>(pn), -1), edges(pattern.edges.size(), -1);
    std::function<void(std::size_t)> bindEdge = [&](std::size_t i) {
        if (i == pattern.edges.size()) {
            if (options.matchHolds && !options.matchHolds(nodes, edges)) return;
            MatchIds m;
            for (int n : nodes) m.push_back(static_cast<std::uint32_t>(n));
            for (int e : edges) m.push_back(static_cast<std::uint32_t>(e));
            out.insert(m);
            return;
        }
        const Edge& pe = pattern.edges[i];
        for (int e = 0; e < static_cast<int>(host.edges.size()); ++e) {
            if (std::find(edges.begin(), edges.begin() + static_cast<long>(i), e) != edges.begin() + static_cast<long>(i)) continue;
            if (!edgeFits(host.edges[static_cast<std::size_t>(e)], pe.kind, nodes[static_cast<std::size_t>(pe.src)],
                          nodes[static_cast<std::size_t>(pe.dst)]))
                continue;
            edges[i] = e;
            bindEdge(i + 1);
            edges[i] = -1;
        }
    };
    std::function<void(int)> bindNode = [&](int p) {
        if (p == pn) {
            if (options.deletedNode >= 0 &&
                degree(host.edges, nodes[static_cast<std::size_t>(options.deletedNode)]) != degree(pattern.edges, options.deletedNode))
                return;
            if (options.nodesHold && !options.nodesHold(nodes)) return;
            bindEdge(0);
            return;
        }
        const int kind = pattern.kinds[static_cast<std::size_t>(p)];
        for (int h = 0; h < hn; ++h) {
            bool clash = false;
            for (int q = 0; q < p; ++q)
                if (nodes[static_cast<std::size_t>(q)] == h &&
                    !(options.identifyWildcards && kind < 0 && pattern.kinds[static_cast<std::size_t>(q)] < 0))
                    clash = true;
            if (clash) continue;
            if (kind >= 0 && host.kinds[static_cast<std::size_t>(h)] != kind) continue;
            nodes[static_cast<std::size_t>(p)] = h;
            bindNode(p + 1);
            nodes[static_cast<std::size_t>(p)] = -1;
        }
    };
    bindNode(0);
    return out;
}

}  // namespace g2d::test::brute
