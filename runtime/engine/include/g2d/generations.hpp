#pragma once
// The thesis tool's `.generation` (its model_gen; the thesis's own age is the
// creation step, Graph::nodeAge): an element an application creates gets one
// more than the highest generation among the elements the application matched
// (nodes, edges and faces of the pattern); the axiom's are 0; kept elements
// keep theirs. Kept only for a grammar that reads it (`pick oldest
// generation`, the `generation` fact): RuleSet::prepareApplication queues
// each application's generation, and RuleSet::applicationDone gives it to
// what that application created, in the order the back end commits them.
#include <cstddef>
#include <vector>

#include "g2d/graph.hpp"

namespace g2d::rt {

struct Match;

// The highest generation among a match's elements.
long long highestGeneration(const Match& m, int nodes, int edges, int faces, const Graph& g);

class GenerationStamps {
public:
    // An application of a match was prepared: it will create generation
    // highestGeneration + 1. The first of a commit notes where its new ids begin.
    void prepared(const Match& m, int nodes, int edges, int faces, const Graph& g);
    // The next prepared application was committed: what it created (the ids
    // since the last) gets its generation.
    void applied(Graph& g);
    // The prepared applications were dropped (a rejected drawing).
    void clear();

private:
    std::vector<long long> queue_;   // per prepared application, in order
    std::size_t next_ = 0;           // the next one committed
    NodeId nodesFrom_ = 0;
    EdgeId edgesFrom_ = 0;
    FaceId facesFrom_ = 0;
};

}  // namespace g2d::rt
