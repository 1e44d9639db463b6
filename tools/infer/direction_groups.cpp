#include "infer/direction_groups.hpp"

#include <cstddef>

namespace g2d::infer {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kParallel = 1e-6;   // degrees: lines this close were drawn parallel

double degrees(double radians) { return radians * 180.0 / kPi; }

// The mean of line directions (as lines: of the doubled angles); a mean that
// is a whole number of degrees to within rounding is that number.
double meanLine(const std::vector<int>& edges, const std::vector<double>& line) {
    double c = 0, s = 0;
    for (int e : edges) {
        c += std::cos(2 * line[static_cast<std::size_t>(e)] * kPi / 180);
        s += std::sin(2 * line[static_cast<std::size_t>(e)] * kPi / 180);
    }
    const double m = wrap180(degrees(std::atan2(s, c)) / 2);
    const double whole = std::round(m);
    return wrap180(std::abs(m - whole) < 1e-6 ? whole : m);
}

// Each edge joins the first group whose first edge is within the tolerance.
std::vector<std::vector<int>> tolerantGroups(const std::vector<double>& line, double tolerance) {
    std::vector<std::vector<int>> groups;
    for (std::size_t e = 0; e < line.size(); ++e) {
        auto g = std::find_if(groups.begin(), groups.end(), [&](const std::vector<int>& members) {
            return lineDistance(line[static_cast<std::size_t>(members.front())], line[e]) <= tolerance;
        });
        if (g == groups.end()) g = groups.insert(groups.end(), std::vector<int>{});
        g->push_back(static_cast<int>(e));
    }
    return groups;
}

// Whether e and f leave a common vertex on rays less than 90° apart: one
// direction would lay them on one ray.
bool shareRay(const DirectedEdge& e, const DirectedEdge& f) {
    const int ends[2] = {e.from, e.to}, fEnds[2] = {f.from, f.to};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            if (ends[i] != fEnds[j]) continue;
            const double a = e.direction + 180.0 * i, b = f.direction + 180.0 * j;
            const double d = std::fabs(std::remainder(a - b, 360.0));
            if (d < 90) return true;
        }
    return false;
}

// A direction the example shows on its own: its edges, its line, and the
// turn a pixel gives its shortest edge (how far apart drawing alone can put two).
struct Seed {
    std::vector<int> edges;
    double line = 0, pixelTurn = 0;
};

class GroupSplit {
public:
    GroupSplit(const std::vector<int>& members, const std::vector<DirectedEdge>& edges, const std::vector<double>& line,
               const DirectionOptions& options)
        : members_(members), edges_(edges), line_(line), options_(options) {}

    // The group's members by seed (one part: the group stays whole).
    std::vector<std::vector<int>> parts() {
        findSeeds();
        mergeSeeds();
        if (seeds_.size() < 2) return {members_};
        std::vector<std::vector<int>> parts(seeds_.size());
        for (int e : members_) parts[static_cast<std::size_t>(nearestSeed(e))].push_back(e);
        return parts;
    }

private:
    // Exactly drawn directions (two or more parallel edges), then each edge
    // sharing a ray with another that none of those holds.
    void findSeeds() {
        std::vector<char> taken(members_.size(), 0);
        for (std::size_t i = 0; i < members_.size(); ++i) {
            if (taken[i]) continue;
            std::vector<int> parallel;
            for (std::size_t j = i; j < members_.size(); ++j)
                if (!taken[j] && lineDistance(lineOf(members_[i]), lineOf(members_[j])) <= kParallel) parallel.push_back(static_cast<int>(j));
            if (parallel.size() < 2) continue;
            Seed seed;
            for (int j : parallel) {
                taken[static_cast<std::size_t>(j)] = 1;
                seed.edges.push_back(members_[static_cast<std::size_t>(j)]);
            }
            seeds_.push_back(seed);
        }
        for (std::size_t i = 0; i < members_.size(); ++i)
            for (std::size_t j = 0; j < members_.size() && !taken[i]; ++j)
                if (i != j && shareRay(edgeOf(members_[i]), edgeOf(members_[j]))) {
                    taken[i] = 1;
                    seeds_.push_back(Seed{{members_[i]}, 0, 0});
                }
        for (Seed& s : seeds_) settle(s);
    }

    // Seeds the example does not tell apart become one, until every two are told apart.
    void mergeSeeds() {
        for (bool merged = true; merged;) {
            merged = false;
            for (std::size_t a = 0; a < seeds_.size() && !merged; ++a)
                for (std::size_t b = a + 1; b < seeds_.size() && !merged; ++b) {
                    if (toldApart(seeds_[a], seeds_[b])) continue;
                    seeds_[a].edges.insert(seeds_[a].edges.end(), seeds_[b].edges.begin(), seeds_[b].edges.end());
                    seeds_.erase(seeds_.begin() + static_cast<std::ptrdiff_t>(b));
                    settle(seeds_[a]);
                    merged = true;
                }
        }
    }

    bool toldApart(const Seed& a, const Seed& b) const {
        for (int e : a.edges)
            for (int f : b.edges)
                if (shareRay(edgeOf(e), edgeOf(f))) return true;
        return lineDistance(a.line, b.line) > a.pixelTurn + b.pixelTurn;
    }

    // An edge's seed: the one holding it, else the nearest (ties: the first).
    int nearestSeed(int e) const {
        int best = 0;
        for (std::size_t s = 0; s < seeds_.size(); ++s) {
            const auto& held = seeds_[s].edges;
            if (std::find(held.begin(), held.end(), e) != held.end()) return static_cast<int>(s);
            if (lineDistance(lineOf(e), seeds_[s].line) < lineDistance(lineOf(e), seeds_[static_cast<std::size_t>(best)].line))
                best = static_cast<int>(s);
        }
        return best;
    }

    void settle(Seed& s) const {
        s.line = meanLine(s.edges, line_);
        double shortest = 1e300;
        for (int e : s.edges) shortest = std::min(shortest, edgeOf(e).length);
        s.pixelTurn = degrees(std::atan2(options_.pixel, shortest));
    }

    double lineOf(int e) const { return line_[static_cast<std::size_t>(e)]; }
    const DirectedEdge& edgeOf(int e) const { return edges_[static_cast<std::size_t>(e)]; }

    const std::vector<int>& members_;
    const std::vector<DirectedEdge>& edges_;
    const std::vector<double>& line_;
    const DirectionOptions& options_;
    std::vector<Seed> seeds_;
};

}  // namespace

DirectionGroups groupDirections(const std::vector<DirectedEdge>& edges, const DirectionOptions& options) {
    std::vector<double> line;
    for (const DirectedEdge& e : edges) line.push_back(wrap180(e.direction));
    std::vector<std::vector<int>> groups;
    for (const std::vector<int>& members : tolerantGroups(line, options.tolerance))
        for (std::vector<int>& part : GroupSplit(members, edges, line, options).parts()) groups.push_back(std::move(part));
    // Numbered by their first edges, as the tolerance alone numbers them.
    std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });
    DirectionGroups out;
    out.groupOf.assign(edges.size(), -1);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        for (int e : groups[g]) out.groupOf[static_cast<std::size_t>(e)] = static_cast<int>(g);
        out.direction.push_back(meanLine(groups[g], line));
    }
    return out;
}

}  // namespace g2d::infer
