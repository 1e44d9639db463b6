#include "g2d/incremental_matches.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace g2d::rt {

IncrementalMatches::IncrementalMatches(RuleSet& rules, const Graph& g) : rules_(rules) {
    for (std::size_t r = 0; r < rules.ruleCount(); ++r) {
        const RuleInfo& info = rules.info(r);
        const int nn = static_cast<int>(info.nodeKinds.size());
        sets_.emplace_back(nn, info.edgeCount, info.pick == Pick::Oldest);
        found_.reset(nn, info.edgeCount);
        rules.findMatches(r, g, found_);
        for (std::size_t i = 0; i < found_.size(); ++i) sets_.back().add(found_.ids(i), g);
    }
}

void IncrementalMatches::region(const Graph& g, const std::vector<NodeId>& changed, int radius) {
    if (seen_.size() < g.nodeCapacity()) seen_.resize(g.nodeCapacity() + g.nodeCapacity() / 2, 0);
    if (++mark_ == 0) {  // wrapped: forget every old mark
        std::fill(seen_.begin(), seen_.end(), 0);
        mark_ = 1;
    }
    area_.clear();
    for (NodeId n : changed)
        if (seen_[n] != mark_) {
            seen_[n] = mark_;
            area_.push_back(n);
        }
    std::size_t begin = 0;
    for (int d = 0; d < radius; ++d) {
        const std::size_t end = area_.size();
        for (std::size_t i = begin; i < end; ++i) {
            const NodeId n = area_[i];
            if (!g.nodeAlive(n)) continue;
            for (EdgeId e = g.firstOut(n); e != kNoId; e = g.nextOut(e)) {
                const NodeId o = g.target(e);
                if (seen_[o] != mark_) {
                    seen_[o] = mark_;
                    area_.push_back(o);
                }
            }
            for (EdgeId e = g.firstIn(n); e != kNoId; e = g.nextIn(e)) {
                const NodeId o = g.source(e);
                if (seen_[o] != mark_) {
                    seen_[o] = mark_;
                    area_.push_back(o);
                }
            }
        }
        begin = end;
    }
}

void IncrementalMatches::update(const Graph& g, const std::vector<NodeId>& changed) {
    if (changed.empty()) return;
    for (std::size_t r = 0; r < sets_.size(); ++r) {
        const RuleInfo& info = rules_.info(r);
        MatchSet& set = sets_[r];
        if (info.radius < 0) {
            // Not local: find them all again.
            set.clear();
            found_.reset(set.nodes(), set.edges());
            rules_.findMatches(r, g, found_);
            for (std::size_t i = 0; i < found_.size(); ++i) set.add(found_.ids(i), g);
            continue;
        }
        region(g, changed, info.radius);
        for (NodeId n : area_) set.removeTouching(n);
        const int nn = set.nodes();
        for (NodeId h : area_) {
            if (!g.nodeAlive(h)) continue;
            for (int p = 0; p < nn; ++p) {
                const int kind = info.nodeKinds[static_cast<std::size_t>(p)];
                if (kind >= 0 && kind != g.nodeKind(h)) continue;
                found_.reset(nn, set.edges());
                rules_.findAnchored(r, g, p, h, found_);
                for (std::size_t i = 0; i < found_.size(); ++i) {
                    const std::uint32_t* ids = found_.ids(i);
                    // Keep it only from its first node inside the area.
                    bool first = true;
                    for (int q = 0; q < p && first; ++q) first = seen_[ids[q]] != mark_;
                    if (first) set.add(ids, g);
                }
            }
        }
    }
}

void IncrementalMatches::verify(const Graph& g, long long step) {
    using Key = std::vector<std::uint32_t>;
    for (std::size_t r = 0; r < sets_.size(); ++r) {
        const MatchSet& set = sets_[r];
        const std::size_t width = static_cast<std::size_t>(set.nodes() + set.edges());
        found_.reset(set.nodes(), set.edges());
        rules_.findMatches(r, g, found_);
        std::vector<Key> all, kept;
        for (std::size_t i = 0; i < found_.size(); ++i) all.emplace_back(found_.ids(i), found_.ids(i) + width);
        for (std::size_t i = 0; i < set.size(); ++i) kept.emplace_back(set.idsAt(i), set.idsAt(i) + width);
        std::sort(all.begin(), all.end());
        std::sort(kept.begin(), kept.end());
        if (all != kept)
            throw std::logic_error("incremental matching lost track of rule " + std::to_string(r) + " after step " +
                                   std::to_string(step) + ": " + std::to_string(kept.size()) + " matches kept, " +
                                   std::to_string(all.size()) + " found");
    }
}

std::size_t IncrementalMatches::memoryBytes() const {
    std::size_t bytes = seen_.capacity() * 4 + area_.capacity() * 4;
    for (const auto& s : sets_) bytes += s.memoryBytes();
    return bytes;
}

}  // namespace g2d::rt
