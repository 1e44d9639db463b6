#pragma once
// Checks one rule: its options, its match (nodes, edges, faces, conditions,
// negative conditions), its lets and, through DaughterChecker, each daughter;
// then the rule-wide lints (rule_lints.cpp). Internal to graph_checker.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sema/context.hpp"
#include "sema/expr_checker.hpp"

namespace g2d::sema {

class RuleChecker {
public:
    RuleChecker(Globals& g, ExprChecker& ec, const ast::RuleDecl& d) : g_(g), ec_(ec), d_(d) {}
    void run();

private:
    friend class DaughterChecker;   // reads the match's names and adds the daughters
    void options();

    // `weight W`: a positive number of literals, constants and parameters.
    void ruleWeight(const ast::Expr& e);

    // `pick random`, `pick oldest`, `pick oldest age`, `pick oldest generation`.
    void checkPick(const ast::RuleOption& o);

    // `f: Kind;` in a match where Kind is a face kind: a face of any corner count.
    bool isCornerlessFace(const ast::NodeStmt& n) const;

    // Declares pattern nodes (first pass) so edges may name nodes written later.
    void declarePatternNodes(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternNode>& out,
                             int indexBase, bool inNac);

    // Declares a name whose declaration failed, so that its uses stay silent.
    void poison(const ast::Ident& name);
    bool isPoisoned(const std::string& name) const;

    std::optional<Span> findName(const std::string& name) const;
    int nodeIndex(const std::string& name) const;

    void declarePatternEdges(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternEdge>& out,
                             int indexBase, const std::string& where);
    std::optional<ir::Condition> condition(const ast::Expr& expr, const std::string& what);

    // A match's (or a negative condition's) faces, after its nodes and
    // edges: `f: Kind(a, b, c)` on its nodes, or `f: Kind` (any corner count,
    // bound through a hidden node at its first corner, appended to `nodes`;
    // see ir::PatternNode::anchorOf). Indices continue from faceBase and nodeBase.
    void declarePatternFaces(const std::vector<ast::MatchStmt>& body, std::vector<ir::PatternFace>& faces,
                             std::vector<ir::PatternNode>& nodes, int faceBase, int nodeBase, bool inNac);

    // Per-element `where` clauses of a pattern, then stand-alone ones.
    void patternConditions(const std::vector<ast::MatchStmt>& body, std::vector<ir::Condition>& out);
    void match();

    bool let(const ast::LetStmt& l, std::vector<ir::Let>& out, const std::vector<ElemBinding>& elems);
    void items();

    void weight(const ast::ProduceBlock& p, ir::Daughter& dg);
    static std::string fmtNumber(double x);

    const ir::PatternEdge* motherEdge(const std::string& name, int* index) const;
    int motherFace(const std::string& name) const;

    void unboundName(const ast::Ident& id, const std::string& what);

    // One `produce` block: a DaughterChecker adds its daughter to the rule.
    void produce(const ast::ProduceBlock& p);
    std::string suggestElement(const std::string& name);

    // An anonymous match edge cannot be kept, so it is always deleted; when the
    // daughter keeps both its ends, that is most likely not what was meant.
    void warnAnonymousEdgesDeleted(const ir::Daughter& dg);

    // A kept face whose corner the daughter deletes goes with that corner.
    void warnKeptFacesLosingCorners(const ir::Daughter& dg);
    void checkAutoPlacement(const ir::Daughter& dg);

    // `intersect`: an application found to intersect is undone through the
    // graph's journal (graph_journal.hpp), which restores positions, radii,
    // edges' ends and faces' corners but not deletions or attributes: such a
    // rule may add, move, rewire, `insert` and `split`, nothing else.
    void checkOnlyAdds();
    // A new edge of no length beside a kept edge: every application undone.
    void warnAlwaysIntersects(const ir::Daughter& d);
    void warnUnusedLets();

    Globals& g_;
    ExprChecker& ec_;
    const ast::RuleDecl& d_;
    ir::Rule rule_;
    std::vector<ElemBinding> bindings_;          // match elements
    std::map<std::string, Span> nacNames_;       // names declared inside negative conditions
    std::vector<LocalVar> locals_;               // lets in scope
    std::vector<LocalVar> finishedLocals_;       // lets out of scope, for the unused warning
    bool neverMatches_ = false;
    std::vector<Diagnostic> pendingWarnings_;    // emitted only if the rule has no errors
    Span limitSpan_;                             // the `limit` option, for diagnostics
};

}  // namespace g2d::sema
