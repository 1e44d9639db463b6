#include "infer/rule_pieces.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

namespace g2d::infer {
namespace {

int nodeOf(const RuleSide& side, int end) { return end >= 0 ? end : static_cast<int>(side.primitive.size()) + (-1 - end); }

int find(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
}

// Where the daughter can put each node relative to interface node `from`:
// along the path of least slack, the displacement is centre ± slack (each
// edge adds its direction times a length in [min, max]: the middle, give or
// take half the range). Dijkstra on the slack.
struct Reach {
    std::vector<double> slack;
    std::vector<Point> centre;
};

Reach reach(const LabelledExample& ex, const RuleSide& side, int interface, int from) {
    const int n = static_cast<int>(side.primitive.size()) + interface;
    struct Step {
        int to;
        double slack;
        Point move;
    };
    std::vector<std::vector<Step>> next(static_cast<std::size_t>(n));
    for (const SideEdge& e : side.edges) {
        const EdgeLabel& l = ex.labels[static_cast<std::size_t>(e.label)];
        const double mid = (l.minLength + l.maxLength) / 2, half = (l.maxLength - l.minLength) / 2;
        const double rad = l.theta * M_PI / 180;
        const Point u{std::cos(rad) * mid, std::sin(rad) * mid};
        const int a = nodeOf(side, e.from), b = nodeOf(side, e.to);
        next[static_cast<std::size_t>(a)].push_back({b, half, u});
        next[static_cast<std::size_t>(b)].push_back({a, half, {-u.x, -u.y}});
    }
    Reach r{std::vector<double>(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity()),
            std::vector<Point>(static_cast<std::size_t>(n), Point{0, 0})};
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    r.slack[static_cast<std::size_t>(from)] = 0;
    open.push({0, from});
    while (!open.empty()) {
        const auto [d, v] = open.top();
        open.pop();
        if (d > r.slack[static_cast<std::size_t>(v)]) continue;
        for (const Step& s : next[static_cast<std::size_t>(v)])
            if (d + s.slack < r.slack[static_cast<std::size_t>(s.to)]) {
                r.slack[static_cast<std::size_t>(s.to)] = d + s.slack;
                const Point c = r.centre[static_cast<std::size_t>(v)];
                r.centre[static_cast<std::size_t>(s.to)] = {c.x + s.move.x, c.y + s.move.y};
                open.push({d + s.slack, s.to});
            }
    }
    return r;
}

// The shortest text that reads back as the same number.
std::string exact(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v == 0 ? 0.0 : v);
    return std::string(buf, r.ptr);
}

// Rounded up a little (a bound, never below the exact one), with room for rounding in the test.
std::string bound(double v) {
    char buf[64];
    const double up = std::ceil(v * 1e6 + 2) / 1e6;   // + the centre's rounding
    const auto r = std::to_chars(buf, buf + sizeof buf, up);
    return std::string(buf, r.ptr);
}

// Rounded to a millionth (the radius allows for it).
std::string vector(Point p) {
    auto round6 = [](double v) { return std::round(v * 1e6) / 1e6; };
    return "(" + exact(round6(p.x)) + ", " + exact(round6(p.y)) + ")";
}

}  // namespace

std::vector<int> sidePieces(const RuleSide& side, int interface) {
    const int n = static_cast<int>(side.primitive.size()) + interface;
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (const SideEdge& e : side.edges) parent[static_cast<std::size_t>(find(parent, nodeOf(side, e.from)))] = find(parent, nodeOf(side, e.to));
    std::vector<int> piece(static_cast<std::size_t>(n), -1), number(static_cast<std::size_t>(n), -1);
    int pieces = 0;
    for (int v = 0; v < n; ++v) {
        const int root = find(parent, v);
        if (number[static_cast<std::size_t>(root)] < 0) number[static_cast<std::size_t>(root)] = pieces++;
        piece[static_cast<std::size_t>(v)] = number[static_cast<std::size_t>(root)];
    }
    return piece;
}

int pieceCount(const RuleSide& side, int interface) {
    int most = -1;
    for (int p : sidePieces(side, interface)) most = std::max(most, p);
    return most + 1;
}

bool keepsConnected(const RuleSides& sides) {
    return pieceCount(sides.left, sides.interface) <= 1 && pieceCount(sides.right, sides.interface) <= 1;
}

std::vector<std::string> nearnessConditions(const LabelledExample& ex, const RuleSide& match, const RuleSide& daughter, int interface) {
    std::vector<std::string> out;
    const std::vector<int> piece = sidePieces(match, interface);
    const int base = static_cast<int>(match.primitive.size());
    // Each piece's first interface node, pieces in the order their first one comes.
    std::vector<int> first, seen;
    for (int k = 0; k < interface; ++k) {
        const int p = piece[static_cast<std::size_t>(base + k)];
        if (std::find(seen.begin(), seen.end(), p) != seen.end()) continue;
        seen.push_back(p);
        first.push_back(k);
    }
    if (first.size() <= 1) return out;
    const Reach r = reach(ex, daughter, interface, static_cast<int>(daughter.primitive.size()) + first[0]);
    const std::string a = "x" + std::to_string(first[0]);
    for (std::size_t p = 1; p < first.size(); ++p) {
        const std::size_t at = daughter.primitive.size() + static_cast<std::size_t>(first[p]);
        if (!std::isfinite(r.slack[at])) continue;   // the daughter does not join them either
        // Written both ways round, so either piece can be looked up near the other.
        const std::string b = "x" + std::to_string(first[p]), c = vector(r.centre[at]), radius = bound(r.slack[at]);
        out.push_back("where distance(" + b + ".pos, " + a + ".pos + " + c + ") <= " + radius + " and distance(" + a + ".pos, " + b +
                      ".pos - " + c + ") <= " + radius + ";");
    }
    return out;
}

}  // namespace g2d::infer
