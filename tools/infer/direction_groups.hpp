#pragma once
// Which edge directions of an example are one direction (Merrell 2023
// §3.3's θ). Drawn examples are a degree or a pixel off, so directions
// within the angle tolerance are one — unless the example itself tells them
// apart, because the tolerance is for drawing noise and must never merge
// directions the example keeps distinct:
//
// - two edges leaving one vertex within the tolerance of each other are
//   two directions (one would put two half-edges of the vertex on one ray);
// - two directions each drawn exactly, by two or more parallel edges, are
//   two when they differ by more than a pixel's turn of their shortest
//   edges (a drawing that repeats a direction exactly is precise there, so
//   a difference it repeats too is meant).
//
// A single edge a few degrees off a direction is noise and joins it.
#include <algorithm>
#include <cmath>
#include <vector>

namespace g2d::infer {

// Into [0, 180): the direction of an undirected line, in degrees.
inline double wrap180(double a) {
    a = std::fmod(a, 180.0);
    if (a < 0) a += 180.0;
    return a >= 180.0 ? 0.0 : a;
}
// Between two line directions, in [0, 90] (179° and 1° are 2° apart).
inline double lineDistance(double a, double b) {
    const double d = std::fabs(wrap180(a - b));
    return std::min(d, 180.0 - d);
}

struct DirectedEdge {
    int from = -1, to = -1;   // vertex indices
    double direction = 0;     // degrees, from -> to (atan2's)
    double length = 0;        // example units
};

struct DirectionGroups {
    std::vector<int> groupOf;        // per edge
    std::vector<double> direction;   // per group: its edges' mean, [0, 180)
};

struct DirectionOptions {
    double tolerance = 10;      // degrees
    double pixel = 1.0 / 40;    // example units: the readers' pixel (40 to a grid cell)
};

DirectionGroups groupDirections(const std::vector<DirectedEdge>& edges, const DirectionOptions& options);

}  // namespace g2d::infer
