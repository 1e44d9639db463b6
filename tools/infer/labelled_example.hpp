#pragma once
// The example as Merrell's model sees it (§3.3, §4.1): every edge gets a
// label (brush, left area, right area, direction θ in [0°, 180°)), cutting
// it gives two half-edges, and every vertex is a primitive: its half-edges
// in counter-clockwise order. Directions within a tolerance are one
// direction unless the example tells them apart (direction_groups.hpp: the
// paper assumes exact self-similarity; drawn examples are a pixel or a
// degree off).
#include <string>
#include <vector>

#include "infer/example_shape.hpp"

namespace g2d::infer {

struct EdgeLabel {
    int brush = 0;
    int left = -1, right = -1;   // area labels left and right of direction theta; -1: none
    double theta = 0;            // degrees, [0, 180)
    double minLength = 0, maxLength = 0;   // the allowed lengths (rigid: equal)
    double unit = 0;                       // > 0: lengths are whole multiples of it
    std::vector<int> edges;      // the example edges with this label
};

// A half-edge label: 2 * edge label + bar. The unbarred half points theta,
// the barred one theta - 180; a half glues to its complement (h ^ 1).
inline int halfLabel(int edgeLabel, bool bar) { return 2 * edgeLabel + (bar ? 1 : 0); }
inline int edgeOfHalf(int half) { return half >> 1; }
inline bool barred(int half) { return (half & 1) != 0; }
inline int complement(int half) { return half ^ 1; }

struct Primitive {
    std::vector<int> halves;     // half-edge labels by direction, ascending in [-180, 180)
    std::vector<int> vertices;   // the example vertices of this type
};

struct LabelledExample {
    ExampleShape shape;
    std::vector<EdgeLabel> labels;
    std::vector<Primitive> primitives;
    std::vector<int> vertexType;       // per example vertex: its primitive
    std::vector<int> edgeLabel;        // per example edge: its label
    std::vector<char> edgeFlipped;     // per example edge: 1 if its label runs to -> from
    int snappedEdges = 0;              // edges whose direction was moved onto another's

    double direction(int half) const;  // degrees, [-180, 180)
};

struct LabelOptions {
    double angleTolerance = 10;   // degrees: directions closer than this are one, unless told apart
    double lengthUnit = 0;        // > 0: every non-rigid label's lengths are whole multiples of it
};

// Throws InputError (crossing or overlapping edges, two edges of a vertex in
// one direction, area labels that disagree around a vertex).
LabelledExample labelExample(const ExampleShape& shape, const LabelOptions& options = {});

}  // namespace g2d::infer
