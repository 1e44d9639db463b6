#pragma once
// What a daughter's rewrite does to the graph, read off its commit
// operations (RewriteProgram) by one visit with a case per operation: the
// operations are what both back ends execute, so what incremental matching,
// parallel steps and the drawing step are told cannot drift from what
// happens.
#include <vector>

#include "g2d/angle_step.hpp"
#include "ir/ir.hpp"

namespace g2d::lower {

struct RewriteProgram;

struct RewriteEffects {
    // The kinds whose elements the rewrite removes, adds or changes (a
    // position, a radius, an edge's ends or attributes, a face's corners;
    // not a style, which no condition reads), and the attributes it writes
    // on kept nodes and faces (valueKey). Sorted.
    std::vector<int> changedKinds;
    std::vector<long long> changedValues;
    // What it deletes or changes, styles included, as pattern slots:
    // deletions first, in the program's order, then kept elements in the
    // daughter's order (a split face after the deleted ones). Parallel steps
    // keep rewrites that write what others read apart (rt::WriteSet).
    std::vector<int> writtenNodes, writtenEdges, writtenFaces;
    bool deletesNodes = false;   // and with them their edges and faces, of any kind
    // For `layout angles`: a kept edge given new ends counts as removed and
    // made again (its drawing is new). Loops cannot be drawn (sema), so
    // their turns' elements are not in it.
    rt::DaughterShape shape;
};

RewriteEffects rewriteEffects(const ir::Program& prog, const ir::Rule& rule, const RewriteProgram& program);

}  // namespace g2d::lower
