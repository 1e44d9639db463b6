#pragma once
// Negative conditions that ask "is some node of kind K near a point?":
//     not { o: K; where distance(o.pos, P) < R; … }
// with P and R read from the match alone. Both back ends search them through
// a spatial index of K's nodes (rt::NearQueries), and incremental matching
// revisits a match only when a K node comes, goes or moves inside its disk,
// instead of searching the rule again after every step.
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "ir/ir.hpp"

namespace g2d::lower {

struct NearNegative {
    int node = -1;                      // o's slot (the negative condition's only node)
    int kind = -1;                      // o's kind
    const ir::Expr* centre = nullptr;   // P: vec2, or vec3 in 3D
    const ir::Expr* radius = nullptr;   // R: float
    bool inclusive = false;             // `<=` rather than `<`
    int key = 0;                        // the match node a test's disk is recorded under:
                                        // the first P or R reads (its change redraws the disk), else the first
};

// The rule's negative condition `nac` in that form, or nothing. Required:
// the rule binds at least one node (its first is the index's key); the
// negative condition has exactly one node, typed, and no edges or faces; one
// of its conditions' `and`-conjuncts is `distance(o.pos, P) < R` (or `<=`,
// either argument order, or `R > distance(…)`) with P and R not reading o;
// no condition reads o's edges or faces (degree, faces), which the index
// does not follow.
std::optional<NearNegative> nearNegative(const ir::Rule& rule, std::size_t nac);

// A pattern node joined to others by distance: a conjunct of one of the
// rule's conditions is `distance(node.pos, P) < R` (or `<=`, either argument
// order, or `R > distance(…)`) with P and R reading only nodes `bound`
// accepts (and at least one). Such a node of a piece not yet bound is
// searched near P (lower::ScanNear, `join`), not among every node of its
// kind: two pieces of a pattern then cost what their neighbourhoods do.
// `kind` is the node's (-1: a wildcard), `key` the first bound node P or R reads.
std::optional<NearNegative> nearJoin(const std::vector<ir::Condition>& conditions, const ir::PatternNode& node, int index,
                                     const std::function<bool(int)>& bound);

}  // namespace g2d::lower
