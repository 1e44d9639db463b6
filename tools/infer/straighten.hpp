#pragma once
// A drawn example is a pixel or a degree off: the edges of one direction
// group (labelled_example.cpp) are not quite parallel, and an edge alone in
// its direction was measured between noisy points. Generation needs
// directions whose loops close exactly (Merrell's drawing step solves for
// lengths with the directions fixed: a loop that does not close forces some
// edge to length 0). So the example is straightened: its vertices move as
// little as possible (least squares) so that the edges of each group are
// parallel, a group at a whole degree keeping it and an averaged one
// settling on the direction of its straightened edges, and an edge alone in
// its direction takes the direction of the straightened drawing.
#include <vector>

#include "infer/example_shape.hpp"

namespace g2d::infer {

// `groups`: per group, its direction (degrees, [0, 180)); `groupOf`: per
// edge, its group. Averaged groups and groups of one edge get the
// straightened directions.
void straighten(const ExampleShape& shape, const std::vector<int>& groupOf, std::vector<double>& groups);

}  // namespace g2d::infer
