#pragma once
// The typed intermediate representation: the contract between the front end
// (compiler/sema) and both back ends (the interpreter and the C++ emitter).
// Plain data: names are resolved to indices, every expression carries its type.
//
// Graph elements are addressed by (ElemClass, index) so that faces (and 3D
// volumes) can join nodes and edges later without changing the addressing.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "diag/source.hpp"
#include "g2d/builtins.hpp"
#include "g2d/elem_class.hpp"
#include "g2d/element_facts.hpp"
#include "g2d/operators.hpp"
#include "g2d/pick.hpp"

namespace g2d::ir {

// ---- types and values --------------------------------------------------------
enum class TypeKind { Int, Float, Bool, String, Vec2, Enum, Void, Vec3 };

struct Type {
    TypeKind kind = TypeKind::Void;
    int enumId = -1;  // for Enum
    static Type of(TypeKind k) { return Type{k, -1}; }
    static Type enumeration(int id) { return Type{TypeKind::Enum, id}; }
    bool operator==(const Type&) const = default;
    bool isNumeric() const { return kind == TypeKind::Int || kind == TypeKind::Float; }
    bool isVector() const { return kind == TypeKind::Vec2 || kind == TypeKind::Vec3; }
};

inline const Type kIntType = Type::of(TypeKind::Int);
inline const Type kFloatType = Type::of(TypeKind::Float);
inline const Type kBoolType = Type::of(TypeKind::Bool);
inline const Type kStringType = Type::of(TypeKind::String);
inline const Type kVec2Type = Type::of(TypeKind::Vec2);
inline const Type kVec3Type = Type::of(TypeKind::Vec3);

struct Vec2 {
    double x = 0, y = 0;
    bool operator==(const Vec2&) const = default;
};

struct Vec3 {
    double x = 0, y = 0, z = 0;
    bool operator==(const Vec3&) const = default;
};

struct EnumValue {
    int enumId = -1;
    int index = -1;
    bool operator==(const EnumValue&) const = default;
};

using Value = std::variant<long long, double, bool, std::string, Vec2, EnumValue, Vec3>;

// ---- elements ------------------------------------------------------------------
using ElemClass = rt::ElemClass;   // g2d/elem_class.hpp

struct ElemRef {
    ElemClass cls = ElemClass::Node;
    int index = -1;
    bool operator==(const ElemRef&) const = default;
    bool operator<(const ElemRef& o) const {
        return cls != o.cls ? cls < o.cls : index < o.index;
    }
};

// Facts every element has, besides its declared attributes.
using ElemFact = rt::ElemFact;   // g2d/element_facts.hpp

// ---- expressions -----------------------------------------------------------------
// The built-in functions are the runtime's (g2d/builtins.hpp): one definition
// that the folder, the interpreter and generated code all call.
using Builtin = rt::Builtin;

enum class ExprOp {
    Literal,     // value
    Param,       // index into Program::params
    Const,       // index into Program::consts
    Local,       // index into the rule's local slots (lets)
    FnArg,       // index into the enclosing function's parameters
    Attr,        // elem, index = attribute of elem's kind
    SelfAttr,    // index = attribute of the element being styled (kind style expressions)
    SelfFact,    // fact of the element being styled
    Placed,      // index = daughter node: its automatic position (`placed` in `at`)
    CompoundValue,   // index = compound, slot = its let: the value of the instance the application runs in (`C.name`)
    Fact,        // elem, fact
    VecX, VecY, VecZ,  // args[0]
    Neg, Not,
    Add, Sub, Mul, Div, Mod, Lt, Le, Gt, Ge, Eq, Ne, And, Or,
    Cond,        // args: cond, then, else
    Call,        // builtin, args
    CallFn,      // index into Program::functions, args
    Count,       // `layout angles`' cost: index = a kind's live elements, or rt::KindCounts::kNodes / kEdges
};

// The runtime's operator for Add … Ne (rt::binaryOp); nullopt for the others.
std::optional<rt::BinaryOp> binaryOperator(ExprOp op);

// A literal as the runtime holds it, and back (the folder computes with the
// runtime's own operations).
rt::Value toRuntime(const Value& v);
Value fromRuntime(const rt::Value& v);

struct Expr {
    ExprOp op = ExprOp::Literal;
    Type type;
    Span span;
    Value value;             // Literal
    int index = -1;          // Param / Const / Local / FnArg / Attr / SelfAttr / CallFn / CompoundValue
    int slot = -1;           // CompoundValue
    ElemRef elem;            // Attr / Fact
    ElemFact fact = ElemFact::Pos;
    Builtin builtin = Builtin::Sin;
    std::vector<Expr> args;
};

// ---- declarations ------------------------------------------------------------------
struct Enum {
    std::string name;
    std::vector<std::string> values;
};

struct Attribute {
    std::string name;
    Type type;
    Expr defaultValue;   // constant: literals, params, consts (no randomness, no elements)
    Span span;
};

struct StyleProp {
    std::string name;    // SVG attribute with `_` for `-`, or a g2d property (tag, r, ...)
    Expr value;          // may read the element's own attributes (SelfAttr) and facts
    Span span;
};

// An edge kind's `layout { … }`: what Merrell 2023's drawing step (`layout
// angles`) needs of its edges, constants known at compile time.
struct EdgeLayout {
    double angle = 0;                  // radians: the direction from source to target
    double minLength = 0, maxLength = 0;
    double unit = 0;                   // > 0: lengths are whole multiples of it (`unit = U;`)
    double bend = 0;                   // > 0: drawn bent after the run (`bend = A;`, radians; rt::bendEdges)
    int left = -1, right = -1;         // face kinds on either side, traced after the run (-1: none)
    Span span;
};

// `layout angles { … }`: new nodes are placed by the drawing step.
struct AngleLayout {
    bool ownCanvas = true;             // false: the grammar's `canvas` is the drawing's (read at run time)
    double canvasMin[2] = {0, 0}, canvasMax[2] = {0, 0};
    int proposals = 5, samples = 10;   // Merrell's I and J
    bool connected = false;            // `connected = true;` (rt::ConnectedGuard)
    double clearance = 0;              // `clearance = C;`: the least distance between a node and an edge not at it (0: 1e-6)
    double bendSegment = 0.1;          // `bend_segment = L;`: bent edges' segment length
    int bendSmooth = 5;                // `bend_smooth = N;`: the turns' averaging window, in segments
    std::optional<Span> bendSettings;  // where the first of those two is given (a warning if nothing bends)
    // Metropolis acceptance (rt::metropolisAccepts): the cost reads
    // parameters, constants and counts (ExprOp::Count); the temperature
    // parameters and constants. No cost: every drawn proposal is accepted.
    std::optional<Expr> cost;
    std::optional<Expr> temperature;
    Span span;
};

struct Kind {
    std::string name;
    ElemClass cls = ElemClass::Node;
    bool directed = false;             // edges
    bool oriented = false;             // faces: `face K oriented`: a new face takes its neighbours' orientation
    std::vector<Attribute> attrs;
    std::vector<StyleProp> style;      // defaults for how elements of this kind are drawn
    std::optional<EdgeLayout> layout;  // edges: `layout { … }`
    Span span;
};

struct Param {
    std::string name;
    Type type;
    Value defaultValue;
    // `in MIN..MAX [step STEP]` (int and float only), folded; a run refuses
    // values outside [min, max]. Both back ends copy them into rt::ParamSpec.
    std::optional<double> min, max, step;
    Span span;
};

struct Const {
    std::string name;
    Type type;
    Expr value;                        // evaluated once per run, in declaration order
    std::optional<Value> folded;       // known at compile time (no params, no randomness)
    Span span;
};

struct Function {
    std::string name;
    std::vector<std::string> paramNames;
    std::vector<Type> paramTypes;
    Type result;
    Expr body;
    Span span;
};

// ---- graphs --------------------------------------------------------------------------
struct AttrAssign {
    int attr = -1;                     // index in the kind's attributes
    Expr value;
};

struct StyleAssign {
    std::string prop;
    int propId = -1;   // index in Program::styleProps
    Expr value;
};

struct AxiomNode {
    std::string name;
    int kind = -1;
    std::optional<Expr> position;      // default (0, 0)
    std::optional<Expr> radius;        // 3D: `{ radius = … }` (default 0)
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

struct AxiomEdge {
    std::string name;
    int kind = -1;
    int src = -1, dst = -1;            // axiom node indices
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

// A face the axiom or a daughter creates.
struct NewFace {
    std::string name;                  // "" when anonymous
    int kind = -1;
    std::vector<int> corners;          // the axiom's or the daughter's node indices, in order
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

struct Axiom {
    std::vector<AxiomNode> nodes;
    std::vector<AxiomEdge> edges;
    std::vector<NewFace> faces;
    Span span;
};

// A node of a mother graph (or of a negative condition).
struct PatternNode {
    std::string name;
    int kind = -1;                     // -1: wildcard, matches any node and is left unchanged
    // >= 0: not written by the user but bound to the first corner of the
    // rule's face `anchorOf` (a face pattern without corners), so that every
    // match binding a face binds a node its changes are marked at
    // (rt::Graph::anchorOf). A wildcard: always kept, never read.
    int anchorOf = -1;
    std::optional<Vec2> sketch;        // drawing position (ordering, automatic placement)
    Span span;
};

struct PatternEdge {
    std::string name;                  // "" when anonymous
    int kind = -1;
    int src = -1, dst = -1;            // node indices; for undirected kinds either orientation matches
    Span span;
};

// A face of a mother graph: `f: Kind(a, b, c)` binds its corners in cyclic
// order (any rotation: each is a match); `f: Kind` a face of any corner count.
struct PatternFace {
    std::string name;
    int kind = -1;
    std::vector<int> corners;          // node indices in cyclic order; empty: any corner count
    int anchor = -1;                   // without corners: the hidden node bound to its first corner
    Span span;
};

struct Condition {
    Expr expr;
    std::vector<ElemRef> deps;         // the pattern elements it reads
};

struct NegativeCondition {
    // Indices continue after the enclosing match's: node outerNodes+i is nodes[i].
    int outerNodes = 0, outerEdges = 0, outerFaces = 0;
    std::vector<PatternNode> nodes;
    std::vector<PatternEdge> edges;
    std::vector<PatternFace> faces;
    std::vector<Condition> conditions;
    Span span;
};

struct Let {
    int slot = -1;
    std::string name;
    Expr value;
};

struct DaughterNode {
    std::string name;
    int motherNode = -1;               // kept mother node, or -1 for a new node
    int kind = -1;                     // -1 only for a kept wildcard
    std::optional<Expr> position;      // `at`; new nodes without it are placed automatically
    std::optional<Vec2> sketch;        // (`at` may read the automatic position as `placed`)
    std::optional<Expr> radius;        // 3D: `{ radius = … }`
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

struct DaughterEdge {
    std::string name;
    int motherEdge = -1;               // kept mother edge, or -1 for a new edge
    int kind = -1;
    int src = -1, dst = -1;            // daughter node indices
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

// A mother face the daughter keeps (`f;` or `f { attr = … };`).
struct KeptFace {
    int motherFace = -1;
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

// A node a turn of a `for` loop names: one of the daughter's (kept or new),
// the turn's corner (`u`) or the next corner (`v`), one the turn creates,
// or one the previous or next turn creates (`prev.m`, `next.m`).
struct LoopNodeRef {
    enum class Scope { Daughter, Var, Local, Prev, Next } scope = Scope::Daughter;
    int index = -1;
};
struct LoopNode {                      // a node each turn creates (or a split makes)
    std::string name;
    int kind = -1;
    Expr position;
    std::optional<Expr> radius;        // 3D
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};
struct LoopEdge {
    int kind = -1;
    LoopNodeRef src, dst;
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};
struct LoopFace {
    int kind = -1;
    std::vector<LoopNodeRef> corners;
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};
// `for (u, v) in f.sides { … }` (a turn per side, u its corner, v the next)
// or `for c in f.corners { … }`, over a matched face's corners in their
// order as the match found them (from the face's first corner).
// Expressions read `u` and `v` as match nodes numbered firstVar, firstVar + 1.
struct FaceLoop {
    int motherFace = -1;
    bool sides = true;
    int firstVar = -1;
    std::vector<LoopNode> nodes;
    std::vector<LoopEdge> edges;
    std::vector<LoopFace> faces;
    Span span;
};

// `Kind(all t)` or `Kind(all t reversed)` in a daughter: one face whose
// corners are node `corner` (the loop's u, v or a node it creates) of every
// turn of loop `loop` (Daughter::loops), in turn order or reversed.
struct RingFace {
    int kind = -1;
    int loop = -1;
    LoopNodeRef corner;                // Scope::Var or Scope::Local
    bool reversed = false;
    std::vector<AttrAssign> assigns;
    std::vector<StyleAssign> styles;
    Span span;
};

// `split f …`: G^3's Split face (rt::splitFace) on matched face motherFace.
// `cond`, read with the corner as match node firstVar, chooses corners; the
// chosen ones cut the face, around a new node (centre), or, two, by a chord.
struct FaceSplit {
    int motherFace = -1;
    int firstVar = -1;
    std::optional<Expr> cond;          // absent: every corner is chosen
    std::optional<LoopNode> centre;    // the node it makes (no name); absent: only a chord (two chosen corners) cuts
    int edgeKind = -1;
    std::vector<AttrAssign> edgeAssigns;
    std::vector<StyleAssign> edgeStyles;
    Span span;
};

struct Daughter {
    std::optional<Expr> weightExpr;    // absent: weight 1
    std::optional<double> weight;      // known at compile time
    bool weightReadsMatch = false;     // weightExpr reads the match: evaluated per application
    std::vector<Let> lets;
    std::vector<DaughterNode> nodes;
    std::vector<DaughterEdge> edges;
    std::vector<NewFace> faces;
    std::vector<KeptFace> keptFaces;
    std::vector<FaceLoop> loops;
    std::vector<RingFace> ringFaces;   // after their loops' turns
    struct Insert { int node, first, second; Span span; };   // daughter node indices
    std::vector<Insert> inserts;       // `insert node between first and second`, in order
    std::vector<FaceSplit> splits;     // after everything else; each face is kept (keptFaces) until it is cut
    std::vector<int> deletedNodes;     // mother nodes not kept (their dangling edges and faces go too)
    std::vector<int> deletedEdges;     // mother edges not kept
    std::vector<int> deletedFaces;     // mother faces not kept
    bool autoPlacement = false;        // some new node is placed automatically
    Span span;
};

using Pick = rt::Pick;   // g2d/pick.hpp

struct Rule {
    std::string name;
    int compound = -1;                 // >= 0: the match of Program::compounds[compound] (never applied)
    long long priority = 0;
    Pick pick = Pick::Random;
    bool ordered = false;              // the match keeps the x and y order of the sketch
    bool merge = false;                // `merge`: coinciding nodes merge after each step
    bool intersect = false;            // `intersect`: an application that would intersect the model is undone
    bool dpo = false;                  // `dpo`: no dangling edges; kept wildcards may share a host node
    bool parallel = false;
    // `weight W`: among the rules of its priority that match, a rule is
    // chosen with probability ∝ W. `weight` is known when compiled;
    // otherwise weightExpr reads parameters.
    double weight = 1;
    std::optional<Expr> weightExpr;
    // `limit N`: at most N steps apply the rule (an int of literals,
    // constants and parameters; GrammarRun::ruleLimits evaluates it).
    std::optional<Expr> limit;
    std::vector<PatternNode> nodes;
    std::vector<PatternEdge> edges;
    std::vector<PatternFace> faces;
    std::vector<Condition> conditions;
    std::vector<NegativeCondition> nacs;
    std::vector<Let> lets;             // evaluated once per application, before the daughter's
    std::vector<Daughter> daughters;
    int localSlots = 0;
    Span span;
};

// `canvas (x0, y0) to (x1, y1);`: the SVG's viewBox, exactly (rt::ViewBox).
// Its corners are constant vec2 expressions (parameters may set them).
struct Canvas {
    Expr lower, upper;
    Span span;
};

struct PriorityConfig {
    std::optional<Expr> limit;
    bool parallel = false;
    bool generation = false;           // every rule of the priority rewrites all its matches in one step (§12.5)
    Span span;
};

// A search slot (lower::PlanStep numbering): the rule's pattern node or edge,
// or, past them, negative condition `nac`'s own.
inline int slotNodeKind(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.nodes.size()) ? r.nodes[i].kind : nac->nodes[i - nac->outerNodes].kind;
}
inline const PatternEdge& slotEdge(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.edges.size()) ? r.edges[i] : nac->edges[i - nac->outerEdges];
}
inline const PatternFace& slotFace(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.faces.size()) ? r.faces[i] : nac->faces[i - nac->outerFaces];
}
inline const PatternNode& slotNode(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.nodes.size()) ? r.nodes[i] : nac->nodes[i - nac->outerNodes];
}

// An entry of a `sequence`: a rule, a compound (Program::compounds), or a
// `repeat` (Program::repeatCounts), which runs the `body` entries after it
// (nested repeats counted in) that many times. Named lists are written out
// where they are named (G^3 §2.4.6: their commands merge into one list).
struct SequenceEntry {
    enum class Kind { Rule, Compound, Repeat } kind = Kind::Rule;
    int index = -1;
    int body = 0;
};
// `compound C { match { … } sequence { … } }`: G^3's compound command (§3.3).
struct Compound {
    std::string name;
    int matchRule = -1;                // its initial primitives: the matches of this rule (Rule::compound)
    // Its lets (the match rule's, in order): per instance, evaluated on its match (rt::CompoundInfo).
    struct Let { std::string name; Type type; };
    std::vector<Let> lets;
    std::vector<SequenceEntry> entries;
    Span span;
};

struct Program {
    bool space3d = false;              // `space 3d;`: positions are vec3
    // Some rule picks by, or some expression reads, `generation`: the
    // runtime keeps it (g2d/generations.hpp).
    bool tracksGenerations = false;
    // `merge within T;`: every rule merges, with tolerance T (a constant
    // expression; <= 0 turns merging off). Rules with the `merge` option
    // merge with it too, or with rt::kDefaultMergeTolerance without one.
    std::optional<Expr> mergeTolerance;
    bool mergeAll = false;
    std::optional<AngleLayout> angleLayout;   // `layout angles { … }`
    std::vector<SequenceEntry> sequence;   // `sequence { … }`, in order
    // Per `repeat N { … }` (SequenceEntry::index): N, an int of constants
    // and parameters, evaluated when the run starts (GrammarRun::repeatCounts).
    std::vector<Expr> repeatCounts;
    std::vector<Compound> compounds;
    std::vector<Enum> enums;
    std::vector<Kind> kinds;
    std::vector<Param> params;
    std::vector<Const> consts;
    std::vector<Function> functions;
    Axiom axiom;
    std::optional<Expr> stepLimit;
    std::map<long long, PriorityConfig> priorities;
    std::vector<std::string> svgDefs;
    std::optional<Canvas> canvas;
    std::vector<Rule> rules;
    // Every style property a per-element assignment sets, in order of first
    // use: the runtime numbers them in this order (rt::StyleStore).
    std::vector<std::string> styleProps;
};

std::string typeName(const Type& t, const Program& p);

// The type of a node's position: vec3 in a grammar declared `space 3d;`.
inline Type positionType(const Program& p) { return p.space3d ? kVec3Type : kVec2Type; }

// Whether rule `r` steps in parallel: `parallel` on the rule or on its
// priority (`priority P parallel;`). A generation is its own way of stepping.
bool runsParallel(const Program& p, const Rule& r);
// Whether the priority of rule `r` is a generation (`priority P generation;`).
bool inGeneration(const Program& p, const Rule& r);

// Whether kept edge `e` of daughter `d` (motherEdge >= 0) joins other nodes
// than it did in the match: its rewrite reconnects it.
bool keptEdgeRewired(const Rule& r, const Daughter& d, const DaughterEdge& e);

}  // namespace g2d::ir
