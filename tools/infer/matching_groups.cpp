#include "infer/matching_groups.hpp"

#include <algorithm>

namespace g2d::infer {
namespace {

struct Search {
    const std::vector<const HierarchyEntry*>& candidates;
    const std::vector<int>& candidateIndex;
    std::vector<RulePiece>& pieces;

    bool groups(const std::vector<GroupEntry>& S);
    bool embed(const std::vector<GroupEntry>& S, const HierarchyEntry& R, int index);
};

// S's winding at unwrapped position t (t >= |S| is the next lap).
int windAt(const std::vector<GroupEntry>& S, int t) {
    const int s = static_cast<int>(S.size());
    return S[static_cast<std::size_t>(t % s)].wind + t / s;
}

struct HalfSet {
    std::vector<int> halves;   // sorted
    std::uint64_t mask = 0;
    explicit HalfSet(const std::vector<GroupEntry>& S) {
        for (const GroupEntry& e : S) {
            halves.push_back(e.half);
            mask |= std::uint64_t{1} << (e.half % 64);
        }
        std::sort(halves.begin(), halves.end());
    }
    bool contains(const HierarchyEntry& R) const {
        return (R.halfMask & ~mask) == 0 && std::includes(halves.begin(), halves.end(), R.halves.begin(), R.halves.end());
    }
};

bool Search::embed(const std::vector<GroupEntry>& S, const HierarchyEntry& R, int index) {
    const auto& RB = R.graph.boundary;
    const int r = static_cast<int>(RB.size()), s = static_cast<int>(S.size());
    std::vector<int> pos(static_cast<std::size_t>(r) + 1);
    // R's first entry goes to every position p0 of S in turn: that finds
    // every cyclic embedding once (another rotation of R only repeats them).
    constexpr int ro = 0;
    auto windR = [&](int, int k) { return RB[static_cast<std::size_t>(k)].wind; };
    {
        for (int p0 = 0; p0 < s; ++p0) {
            if (S[static_cast<std::size_t>(p0)].half != RB[static_cast<std::size_t>(ro)].half) continue;
            pos[0] = p0;
            pos[static_cast<std::size_t>(r)] = p0 + s;
            // Depth-first over the positions of R's entries 1..r-1, in order.
            std::vector<int> next(static_cast<std::size_t>(r), 0);
            int k = 1;
            if (r > 1) next[1] = p0 + 1;
            while (true) {
                if (k == r) {
                    // An embedding: close each gap and match it.
                    const std::size_t mark = pieces.size();
                    RulePiece piece;
                    piece.graph = index;
                    piece.leftEntry.assign(static_cast<std::size_t>(r), -1);
                    for (int q = 0; q < r; ++q)
                        piece.leftEntry[static_cast<std::size_t>((ro + q) % r)] = S[static_cast<std::size_t>(pos[static_cast<std::size_t>(q)] % s)].origin;
                    pieces.push_back(piece);
                    bool ok = true;
                    for (int q = 0; q < r && ok; ++q) {
                        const int from = pos[static_cast<std::size_t>(q)] + 1, to = pos[static_cast<std::size_t>(q) + 1];
                        if (from == to) continue;
                        std::vector<GroupEntry> gap;
                        for (int t = from; t < to; ++t) {
                            GroupEntry e = S[static_cast<std::size_t>(t % s)];
                            e.wind = windAt(S, t);
                            gap.push_back(e);
                        }
                        ok = groups(gap);
                    }
                    if (ok) return true;
                    pieces.resize(mark);
                    if (r == 1) break;
                    k = r - 1;   // try the last entry further on
                    next[static_cast<std::size_t>(k)] = pos[static_cast<std::size_t>(k)] + 1;
                    continue;
                }
                bool placed = false;
                const int last = p0 + s - (r - k);   // leave room for the entries after k
                for (int t = next[static_cast<std::size_t>(k)]; t <= last; ++t) {
                    if (S[static_cast<std::size_t>(t % s)].half != RB[static_cast<std::size_t>((ro + k) % r)].half) continue;
                    if (windAt(S, t) - windAt(S, p0) != windR(ro, k) - windR(ro, 0)) continue;
                    pos[static_cast<std::size_t>(k)] = t;
                    placed = true;
                    break;
                }
                if (placed) {
                    ++k;
                    if (k < r) next[static_cast<std::size_t>(k)] = pos[static_cast<std::size_t>(k) - 1] + 1;
                    continue;
                }
                --k;   // backtrack
                if (k == 0) break;
                next[static_cast<std::size_t>(k)] = pos[static_cast<std::size_t>(k)] + 1;
            }
        }
    }
    return false;
}

bool Search::groups(const std::vector<GroupEntry>& S) {
    const HalfSet have(S);
    for (std::size_t c = 0; c < candidates.size(); ++c) {
        const HierarchyEntry& R = *candidates[c];
        if (R.graph.boundary.empty() || R.graph.boundary.size() > S.size()) continue;
        if (!have.contains(R)) continue;
        if (embed(S, R, candidateIndex[c])) return true;
    }
    return false;
}

}  // namespace

bool findMatchingGroups(const std::vector<GroupEntry>& boundary, const std::vector<const HierarchyEntry*>& candidates,
                        const std::vector<int>& candidateIndex, std::vector<RulePiece>& pieces) {
    pieces.clear();
    Search search{candidates, candidateIndex, pieces};
    return search.groups(boundary);
}

}  // namespace g2d::infer
