#pragma once
// `layout angles`: after the derivation, the faces of the drawing become the
// graph's faces (each edge kind names the face kinds on its sides), so
// outputs have faces like any grammar's: SVG, JSON, OBJ.
#include "g2d/derivation.hpp"

namespace g2d::rt {

// Adds the bounded faces traceFaces finds (angle_faces.hpp), with their
// kinds' default attributes (RuleSet::addFaceWithDefaults), at `age`,
// and their holes (Graph::setFaceHoles).
// Returns how many.
std::size_t addDrawnFaces(Graph& g, RuleSet& rules, const AngleLayoutSpec& spec, long long age);

}  // namespace g2d::rt
