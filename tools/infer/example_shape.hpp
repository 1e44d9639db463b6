#pragma once
// An example shape for `g2d infer`, whatever file it came from: a plane
// straight-line drawing whose edges carry a label ("brush") and an area label
// on each side (Merrell 2023 §3.3). Plain data: the readers fill it, the
// labelling (labelled_example.hpp) reads it.
#include <string>
#include <vector>

namespace g2d::infer {

struct Point {
    double x = 0, y = 0;  // y up, in example units
};

struct EdgeBrush {
    std::string name;        // for the grammar's comments and kind names
    std::string color;       // as the input gives it ("" if none)
    bool rigid = false;      // its edges keep their length from the example
    double minLength = 0;    // the allowed length range; both 0: not given
    double maxLength = 0;
    double unit = 0;         // > 0: lengths are whole multiples of it (the app's Rigid Tiled, Tile Length)
    double bend = 10;        // degrees a segment may turn when bending is asked for (the app's Bend; Appendix B)
};

struct AreaLabel {
    std::string name;
    std::string color;       // fill, as the input gives it
};

struct ExampleEdge {
    int from = -1, to = -1;             // vertex indices
    int brush = 0;                      // index into ExampleShape::brushes
    int leftArea = -1, rightArea = -1;  // area label on each side of from -> to (y up); -1: none
    std::string where;                  // where in the input, for messages ("data[41], edge 3", "line 12")
};

struct ExampleShape {
    std::string name;
    std::string source;                     // the input's path, for messages
    std::vector<Point> vertices;
    std::vector<std::string> vertexWhere;   // per vertex, where the input has it
    std::vector<ExampleEdge> edges;
    std::vector<EdgeBrush> brushes;         // at least one
    std::vector<AreaLabel> areas;
    // The drawing area of generated shapes, in example units: the input's own
    // (the author's `Extents`) or none (0 x 0: the reader of the shape decides).
    double canvasWidth = 0, canvasHeight = 0;
};

// A bad input: the message says where (file and position in it).
struct InputError {
    std::string message;
};

}  // namespace g2d::infer
