#pragma once
// A daughter's rewrite as an ordered program: what both back ends do, decided
// once. The interpreter executes it operation by operation; the C++ emitter
// prints each operation as code. Neither decides anything the program does
// not say: the order of evaluation (which random draws and which error come
// first), the checks and their messages, the order of the graph updates, and
// which changes are recorded for incremental matching.
//
// A rewrite has two parts, the contract of rt::RuleSet (prepare, commit):
//   prepare  reads the graph before the step: evaluates every value into a
//            register (typed, written once), in the daughter's order;
//   commit   writes the graph: reads only the match, registers and literals.
// Operands are numbers (match slots, registers, handles), never names.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ir/ir.hpp"
#include "lower/rewrite_effects.hpp"

namespace g2d::lower {

// A value a commit writes: a register prepare filled, or a literal of the
// grammar written as it is.
struct Operand {
    int reg = -1;                       // >= 0: a register
    const ir::Expr* literal = nullptr;  // else: an ir::ExprOp::Literal
    ir::Type type;
};

// ---- prepare -----------------------------------------------------------------
struct EvalLocal {          // a `let` (the rule's, then the daughter's), into the rule's local slot
    int slot;
    const ir::Expr* value;
};
// Automatic placement (rt::placementFrame): the frame from the mother's sketch
// to the match, then each target's sketch through it, checked finite.
struct Place {
    struct Target {
        int daughterNode;
        ir::Vec2 sketch;
        Span span;
        std::string message;            // when the position is not finite
    };
    // The pattern nodes that take part: all but wildcards without a sketch
    // position (the thesis tool's dangling-edge ends, which it left out).
    std::vector<int> members;
    std::vector<ir::Vec2> motherSketch;           // per member
    // The reference pairs, (daughter sketch, pattern node): the kept nodes,
    // or, where none is kept, every pattern node (its mother sketch).
    std::vector<std::pair<ir::Vec2, int>> refs;
    std::optional<std::pair<int, int>> directed;  // the first directed non-loop pattern edge between members (indices into members)
    bool space3d = false;                         // positions are vec3: z is the references' mean z
    std::vector<Target> targets;
};
struct Eval {               // reg <- value
    int reg;
    const ir::Expr* value;
};
struct EvalPosition {       // reg <- value, which must be a finite vector
    int reg;
    const ir::Expr* value;
    std::string message;    // at value->span when it is not
};
struct TakePlaced {         // reg <- the automatic position of a daughter node
    int reg;
    int daughterNode;
};
struct PrepareLoop { int loop; };   // RewriteProgram::loops[loop]: its corners, and each turn's values
using PrepareOp = std::variant<EvalLocal, Place, Eval, EvalPosition, TakePlaced, PrepareLoop>;

// ---- commit --------------------------------------------------------------------
// Nodes of the daughter are addressed by handle (= daughter node index), its
// edges by edge handle (= daughter edge index).
struct AttrWrite {
    int attr;
    Operand value;
};
struct DeleteEdge { int matchEdge; };
struct BindNode { int handle; int matchNode; };          // a kept node
struct CreateNode {
    int handle, kind;
    int posReg;
    std::vector<AttrWrite> attrs;                        // the rest keep the kind's defaults
};
struct Rewire {                                          // a kept edge given new ends (node handles)
    int matchEdge;
    int src, dst;
    int kind;                                            // as the daughter names it (the drawing's shape; -1: any)
};
struct DeleteNode { int matchNode; };                    // with its remaining edges
struct SetPos { int handle; int reg; };
struct SetRadius { int handle; Operand value; };         // G^3's node radius (3D)
struct SetNodeAttr { int handle, kind; AttrWrite write; };   // a kept node's attribute (no change recorded)
struct TouchNodeValues { int handle; };                  // record that a kept node's attributes changed
struct SetNodeStyle { int handle; const ir::StyleAssign* style; Operand value; };
struct BindEdge { int handle; int matchEdge; };          // a kept edge
struct SetEdgeAttr { int handle, kind; AttrWrite write; };   // a kept edge's attribute (no change recorded)
struct TouchEdge { int handle; };                        // record that a kept edge changed (its ends)
struct CreateEdge {
    int handle, kind;
    int src, dst;                                        // node handles
    std::vector<AttrWrite> attrs;
};
struct SetEdgeStyle { int handle; const ir::StyleAssign* style; Operand value; };
// Faces are addressed by face handle: the daughter's new faces first, then
// the faces it keeps (ir::Daughter::keptFaces order).
struct DeleteFace { int matchFace; };                    // (a face a node deletion removed already: nothing)
struct BindFace { int handle; int matchFace; };          // a kept face
// A write to a kept face is skipped when the face is gone (`ifAlive`): a
// node deletion of this rewrite, or another application of the same
// parallel step, may have removed it with a corner. New faces are there.
struct SetFaceAttr { int handle, kind; AttrWrite write; bool ifAlive; };   // a kept face's attribute (no change recorded)
struct TouchFace { int handle; bool ifAlive; };          // record that a kept face's attributes changed
struct CreateFace {
    int handle, kind;
    std::vector<int> corners;                            // node handles, in order (>= 3, distinct)
    std::vector<AttrWrite> attrs;
    bool orient;                                         // the kind is `oriented` (rt::addDaughterFace)
};
struct SetFaceStyle { int handle; const ir::StyleAssign* style; Operand value; bool ifAlive; };
struct InsertBetween { int node, first, second; };    // node handles (rt::Graph::insertBetween)
struct CommitLoop { int loop; };    // RewriteProgram::loops[loop]: every turn's create, then every turn's link
// A face over one node of every turn of committed loop `loop` (ir::RingFace),
// in turn order or reversed: node `turnNode` of the turn in the loop's
// numbering less outerNodes (0: its corner u, 1: v, 2 + i: its new node i).
struct CreateRingFace {
    int handle, kind;
    int loop, turnNode;
    bool reversed;
    std::vector<AttrWrite> attrs;
    bool orient;   // the kind is `oriented` (rt::addDaughterFace)
};
struct SplitFace { int face; int split; };   // face handle; RewriteProgram::splits[split] (rt::splitFace)
using CommitOp = std::variant<DeleteFace, DeleteEdge, BindNode, CreateNode, Rewire, DeleteNode, SetPos, SetRadius, SetNodeAttr,
                              TouchNodeValues, SetNodeStyle, BindEdge, SetEdgeAttr, TouchEdge, CreateEdge, SetEdgeStyle,
                              BindFace, SetFaceAttr, TouchFace, CreateFace, SetFaceStyle, InsertBetween, CommitLoop, CreateRingFace,
                              SplitFace>;

// A `for` loop (ir::FaceLoop), one turn per corner of the matched face, from
// its first corner. Prepare takes the corners (before the step changes
// anything) and evaluates `prepare` per turn into that turn's registers.
// Commit runs `create` for every turn (the turns' new nodes), then `link`
// for every turn (edges and faces, which may join neighbouring turns' nodes).
// In their operations, node handles below `outerNodes` are the daughter's;
// then come the turn's corner u (outerNodes) and the next corner v (+1), its
// new nodes (+2 + i), the previous turn's (+2 + L + i) and the next turn's
// (+2 + 2L + i), L = localNodes. Edge and face handles are per turn.
struct LoopProgram {
    int matchFace = -1;
    bool sides = true;
    int firstVar = -1;                  // expressions read u and v as match nodes firstVar and firstVar + 1
    int outerNodes = 0, localNodes = 0;
    std::vector<PrepareOp> prepare;
    std::vector<ir::Type> registers;
    std::vector<CommitOp> create, link;
    int edgeHandles = 0, faceHandles = 0;
    int nodeHandles() const { return outerNodes + 2 + 3 * localNodes; }
};

// G^3's Split face (ir::FaceSplit, rt::splitFace). Loop `loop` takes the
// face's corners in prepare and evaluates whether each is chosen into its
// register chosenReg (-1: every corner is). Commit runs `makeCentre` to make
// the new node on node handle `to` (empty: a chord only cuts), and
// `makeEdge`, once per edge, to make edge handle `edgeHandle` from node
// handle `from` to `to`; the cut itself is the runtime's. Their operands are
// read once per edge: a back end must not use a register up.
struct SplitProgram {
    int loop = -1, chosenReg = -1;
    int from = -1, to = -1, edgeHandle = -1;
    std::vector<CommitOp> makeCentre, makeEdge;
};

struct RewriteProgram {
    std::vector<PrepareOp> prepare;
    std::vector<CommitOp> commit;
    std::vector<LoopProgram> loops;     // the `for` loops, then the splits' corner loops
    std::vector<SplitProgram> splits;
    std::vector<ir::Type> registers;
    int nodeHandles = 0, edgeHandles = 0, faceHandles = 0;
    bool placement = false;             // prepare has a Place (the `placed` positions exist)
    RewriteEffects effects;             // read off the commit operations (rewriteEffects)
};

// For std::visit with one overload per operation and no catch-all: an
// operation a back end does not handle is a compile error there.
template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

// The rewrite of daughter `daughter` of `rule`.
RewriteProgram lowerRewrite(const ir::Program& prog, const ir::Rule& rule, std::size_t daughter);

// The program as text, one operation a line (tests, and reading what a rule does).
std::string printRewrite(const ir::Program& prog, const ir::Rule& rule, const RewriteProgram& p);

}  // namespace g2d::lower
