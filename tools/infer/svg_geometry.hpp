#pragma once
// Turns the SVG reader's drawn elements (already transformed into example
// units, y up) into a plane graph: merged vertices, edges split at
// T-junctions and crossings, duplicates removed, and each edge's area labels
// found from the filled shapes beside it.
#include <string>
#include <vector>

#include "infer/example_shape.hpp"

namespace g2d::infer::svg {

struct Outline {
    std::vector<Point> points;
    bool closed = false;
};

struct DrawnElement {
    std::string tag;                 // "line", "rect", ... for messages
    long line = 0;                   // in the SVG file
    std::vector<Outline> outlines;
    int stroke = -1;                 // index into the stroke colours; -1: draws no edges
    int fill = -1;                   // index into the fill colours; -1: no area
    bool evenOdd = false;            // fill-rule
};

struct PlanarInput {
    std::string path;                        // the file, for messages
    std::vector<DrawnElement> elements;      // in document (painting) order
    std::vector<std::string> strokeColors;   // for messages
    double tolerance = 0;                    // closer points are one vertex (example units)
    double svgUnit = 1;                      // example unit in user units, to print positions as drawn
};

// Fills out.vertices, vertexWhere and edges; an edge's brush and areas are
// indices into the input's stroke and fill colours (the caller renumbers
// them). Throws InputError for an isolated point or an edge drawn twice
// with different strokes.
void planarize(const PlanarInput& in, ExampleShape& out);

}  // namespace g2d::infer::svg
