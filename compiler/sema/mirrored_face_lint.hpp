#pragma once
// A warning for a face pattern written against the orientation of every face
// of its kind the grammar makes: a face never matches its mirror image
// (language.md §8.2), so the pattern never matches.
#include "sema/context.hpp"

namespace g2d::sema {

void warnMirroredFacePatterns(Globals& g);

}  // namespace g2d::sema
