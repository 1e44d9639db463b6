#pragma once
// What the writers need to know of a grammar beside its graph: the names of
// its kinds, attributes and enum values, and whether it is in 3D. Its own
// header because every back end provides one (GrammarRun::jsonSchema) and
// the embedding API should not pull in the writers for it.
#include <string>
#include <vector>

namespace g2d::rt {

struct JsonSchema {
    std::vector<std::string> kindNames;
    std::vector<std::vector<std::string>> attrNames;      // per kind
    std::vector<std::vector<std::string>> enumValueNames; // per enum
    bool space3d = false;                                 // positions have a z; nodes a radius
};

}  // namespace g2d::rt
