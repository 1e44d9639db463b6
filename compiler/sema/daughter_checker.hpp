#pragma once
// Checks one `produce` block of a rule and adds its daughter (ir::Daughter) to
// the rule: kept, changed and new nodes, edges and faces, lets, loops over a
// face, inserts and splits; then what the daughter deletes of the match.
// Internal to graph_checker.
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sema/rule_checker.hpp"

namespace g2d::sema {

class DaughterChecker {
public:
    DaughterChecker(RuleChecker& rule, const ast::ProduceBlock& p)
        : r_(rule), g_(rule.g_), ec_(rule.ec_), rule_(rule.rule_), p_(p) {}

    void run();

private:
    // A name given once per daughter; reports a second use.
    bool claim(const ast::Ident& id);
    // What the daughter's expressions may read.
    ExprEnv exprEnv() const;
    // The daughter node `id` names; naming a matched node keeps it.
    int daughterNode(const ast::Ident& id, const char* role = "edge endpoint");
    void declareNodes();
    void statements();
    void finish();
    // A face the daughter creates, on its nodes (kept or new), in order.
    void daughterFace(const ast::FaceStmt& f, const ExprEnv& env);
    // A node the daughter (or a loop of it) creates: named, not readable.
    static ElemBinding newNodeBinding(const ast::Ident& name, int kind, const std::string& creator, const std::string& readable);
    // `for (u, v) in f.sides { … }` or `for c in f.corners { … }`: what each
    // turn creates, on the turn's corners, the daughter's nodes, its own new
    // nodes and the neighbouring turns' (`prev.m`, `next.m`).
    void daughterLoop(const ast::ForBlock& fb, ExprEnv env);
    // `Kind(all t)` / `Kind(all t reversed)`: one face over node t of every
    // turn of the loop that names t (read after all the daughter's loops).
    void ringFace(const ast::FaceStmt& f);
    // `split f [around Kind at POS {…}] with EdgeKind {…} [for c in f.corners
    // where COND];`: the corner `c` reads as a wildcard node, like a loop's.
    void daughterSplit(const ast::SplitStmt& sp, ExprEnv env);
    // The daughter node for a mother node, keeping it if it is not kept yet
    // (a kept edge keeps its endpoints; wildcards are always kept).
    int keepEndpointOf(int mother);
    // Warns about `insert m between a and c` when a matched face has a and c
    // as corners, never next to each other (a diagonal), and no matched face
    // has them as a side: the matched faces do not grow.
    void diagonalInsert(const ast::InsertStmt& ins, int first, int second);

    RuleChecker& r_;
    Globals& g_;
    ExprChecker& ec_;
    ir::Rule& rule_;
    const ast::ProduceBlock& p_;
    ir::Daughter dg_;
    std::vector<ElemBinding> elems_;            // what expressions read: the match, then the new nodes
    std::map<int, int> keptNodes_;              // mother node -> daughter node
    std::map<int, int> keptEdges_;              // mother edge -> daughter edge
    std::map<std::string, Span> named_;         // names used in this daughter
    std::map<std::string, int> newNodes_;       // new node -> daughter node
    struct PendingNode {                        // a node statement of pass 1, finished in pass 2
        const ast::NodeStmt* stmt;
        int index;
    };
    std::vector<PendingNode> pendingNodes_;
    // `e;` / `f;` statements keeping a matched edge or face, with its index.
    std::vector<std::pair<const ast::NodeStmt*, int>> keptEdgeStmts_, keptFaceStmts_;
    // A kept edge's ends, resolved once the whole daughter is read (a later
    // statement may name them).
    struct KeptEdgeEnds {
        std::size_t edge;                       // in dg_.edges
        int motherSrc, motherDst;
    };
    std::vector<KeptEdgeEnds> keptEdgeEnds_;
    // The loops' variables and new nodes by name: the loop (dg_.loops) and the node; -1: its loop had errors.
    std::map<std::string, std::pair<int, ir::LoopNodeRef>> loopNodes_;
    std::vector<const ast::FaceStmt*> ringFaces_;
};

}  // namespace g2d::sema
