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
#include "g2d/operators.hpp"

namespace g2d::ir {

// ---- types and values --------------------------------------------------------
enum class TypeKind { Int, Float, Bool, String, Vec2, Enum, Void };

struct Type {
    TypeKind kind = TypeKind::Void;
    int enumId = -1;  // for Enum
    static Type of(TypeKind k) { return Type{k, -1}; }
    static Type enumeration(int id) { return Type{TypeKind::Enum, id}; }
    bool operator==(const Type&) const = default;
    bool isNumeric() const { return kind == TypeKind::Int || kind == TypeKind::Float; }
};

inline const Type kIntType = Type::of(TypeKind::Int);
inline const Type kFloatType = Type::of(TypeKind::Float);
inline const Type kBoolType = Type::of(TypeKind::Bool);
inline const Type kStringType = Type::of(TypeKind::String);
inline const Type kVec2Type = Type::of(TypeKind::Vec2);

struct Vec2 {
    double x = 0, y = 0;
    bool operator==(const Vec2&) const = default;
};

struct EnumValue {
    int enumId = -1;
    int index = -1;
    bool operator==(const EnumValue&) const = default;
};

using Value = std::variant<long long, double, bool, std::string, Vec2, EnumValue>;

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
enum class ElemFact { Pos, Age, Id, Degree, InDegree, OutDegree };

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
    Fact,        // elem, fact
    VecX, VecY,  // args[0]
    Neg, Not,
    Add, Sub, Mul, Div, Mod, Lt, Le, Gt, Ge, Eq, Ne, And, Or,
    Cond,        // args: cond, then, else
    Call,        // builtin, args
    CallFn,      // index into Program::functions, args
};

// The runtime's operator for Add … Ne (rt::binaryOp); nullopt for the others.
std::optional<rt::BinaryOp> binaryOperator(ExprOp op);

struct Expr {
    ExprOp op = ExprOp::Literal;
    Type type;
    Span span;
    Value value;             // Literal
    int index = -1;          // Param / Const / Local / FnArg / Attr / SelfAttr / CallFn
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

struct Kind {
    std::string name;
    ElemClass cls = ElemClass::Node;
    bool directed = false;             // edges
    std::vector<Attribute> attrs;
    std::vector<StyleProp> style;      // defaults for how elements of this kind are drawn
    Span span;
};

struct Param {
    std::string name;
    Type type;
    Value defaultValue;
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

struct Axiom {
    std::vector<AxiomNode> nodes;
    std::vector<AxiomEdge> edges;
    Span span;
};

// A node of a mother graph (or of a negative condition).
struct PatternNode {
    std::string name;
    int kind = -1;                     // -1: wildcard, matches any node and is left unchanged
    std::optional<Vec2> sketch;        // drawing position (ordering, automatic placement)
    Span span;
};

struct PatternEdge {
    std::string name;                  // "" when anonymous
    int kind = -1;
    int src = -1, dst = -1;            // node indices; for undirected kinds either orientation matches
    Span span;
};

struct Condition {
    Expr expr;
    std::vector<ElemRef> deps;         // the pattern elements it reads
};

// One step of a search plan: bind one more pattern element, or test.
struct PlanStep {
    enum class Op {
        ScanNodes,    // node := each host node of its kind (or any node for a wildcard)
        ExtendEdge,   // edge := each edge incident to bound node `from`; node := its other end
        ConnectEdge,  // edge := each edge between two bound nodes
        Check,        // evaluate conditions[condition]
    } op = Op::ScanNodes;
    int node = -1;
    int edge = -1;
    int from = -1;
    bool fromIsSource = true;          // ExtendEdge: `from` is the edge's source
    int condition = -1;
};

struct NegativeCondition {
    // Indices continue after the enclosing match's: node outerNodes+i is nodes[i].
    int outerNodes = 0, outerEdges = 0;
    std::vector<PatternNode> nodes;
    std::vector<PatternEdge> edges;
    std::vector<Condition> conditions;
    std::vector<PlanStep> plan;
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

struct Daughter {
    std::optional<Expr> weightExpr;    // absent: weight 1
    std::optional<double> weight;      // known at compile time
    std::vector<Let> lets;
    std::vector<DaughterNode> nodes;
    std::vector<DaughterEdge> edges;
    std::vector<int> deletedNodes;     // mother nodes not kept (their dangling edges go too)
    std::vector<int> deletedEdges;     // mother edges not kept
    bool autoPlacement = false;        // some new node is placed automatically
    // The kinds of the elements applying this daughter removes, adds or
    // changes (a position, the kind, an edge's ends or attributes; not a
    // style, which no condition reads), and the attributes it writes on
    // kept nodes (valueKey; those alone leave a node's kind out of
    // changedKinds). Sorted. Removing a node also removes its edges, of any
    // kind: a rule reading degrees sees that through deletedNodes.
    std::vector<int> changedKinds;
    std::vector<long long> changedValues;
    Span span;
};

enum class Pick { Random, Oldest };

// A node attribute as one number (Rule::readValues, Daughter::changedValues).
inline long long valueKey(int kind, int attribute) { return static_cast<long long>(kind) << 32 | static_cast<unsigned>(attribute); }

// What a pattern node's matches read of the edges at its host beyond what
// the other pattern nodes read:
inline constexpr std::uint8_t kReadsOutEdges = 1, kReadsInEdges = 2;

enum class IncidenceRead {
    None,          // nothing (another end reads the edges between them)
    PatternEdges,  // the pattern's own edges: adding or removing others keeps its matches
    AllEdges,      // every edge (degrees, negative conditions): any edge change may matter
};

struct Rule {
    std::string name;
    long long priority = 0;
    Pick pick = Pick::Random;
    bool ordered = false;              // the match keeps the x and y order of the sketch
    bool parallel = false;
    std::vector<PatternNode> nodes;
    std::vector<PatternEdge> edges;
    std::vector<Condition> conditions;
    std::vector<PlanStep> plan;
    // anchoredPlans[i]: the search with node i already bound (incremental
    // matching re-finds matches around the nodes a step changed).
    std::vector<std::vector<PlanStep>> anchoredPlans;
    std::vector<NegativeCondition> nacs;
    // How far (in edges) from a changed node a match of this rule can be
    // affected: 0 without negative conditions (a match reads only its own
    // elements), else the depth of the deepest negative-condition node;
    // -1 when a negative condition has a part not connected to the match
    // (then any change anywhere may matter).
    int repairRadius = 0;
    // Per match node: which changes among the host node's edges alone (an
    // edge added or removed) can make or break a match binding it there.
    // Every edge between two match nodes is read from one end only, so a
    // hub's edge changes need not revisit every match binding the hub.
    std::vector<IncidenceRead> readsIncidence;
    // Per match node: which of its host's edge lists it reads, as
    // kReadsOutEdges | kReadsInEdges (0 where readsIncidence is None). A node
    // reading only the pattern's edges reads the directions of its pattern
    // edges (an undirected one or a loop: both); one reading every edge,
    // both. A host whose outgoing edges alone changed is then not searched
    // again at a node reading only incoming ones, and vice versa: a path's
    // split revisits the source's end only.
    std::vector<std::uint8_t> readDirections;
    // Per match node: a search anchored there at a node the step created
    // cannot add a match, so repair skips it. Such a match binds one of the
    // node's edges, all new, and is added from the first of its pattern
    // nodes whose host is searched: an earlier pattern node joined to this
    // one by a pattern edge and reading incidences is (both ends of a new
    // edge are marked).
    std::vector<bool> newHostAddsNothing;
    // Per match node: the distinct kinds of its pattern edges, all of which a
    // host must have had (rt::Graph::edgeKindsAt) to be searched there; empty
    // where that test cannot skip anything (no pattern edges, or a grammar of
    // one edge kind: every node with an edge has it).
    std::vector<std::vector<int>> neededEdgeKinds;
    // The kinds (node and edge kinds share Program::kinds' numbering) whose
    // elements a change of can change this rule's matches: those of its
    // pattern and its negative conditions (a wildcard node: every node kind;
    // an edge without a kind: every edge kind), and every edge kind where a
    // condition reads a degree (readsDegrees). Sorted.
    std::vector<int> readKinds;
    bool readsDegrees = false;
    // The node attributes its conditions (and its negative conditions')
    // read, as valueKey(kind, attribute). Sorted. A step that only writes
    // other attributes of a node leaves the rule's matches binding it as
    // they were.
    std::vector<long long> readValues;
    std::vector<Let> lets;             // evaluated once per application, before the daughter's
    std::vector<Daughter> daughters;
    int localSlots = 0;
    Span span;
};

struct PriorityConfig {
    std::optional<Expr> limit;
    bool parallel = false;
    Span span;
};

// A search slot (ir::PlanStep numbering): the rule's pattern node or edge,
// or, past them, negative condition `nac`'s own.
inline int slotNodeKind(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.nodes.size()) ? r.nodes[i].kind : nac->nodes[i - nac->outerNodes].kind;
}
inline const PatternEdge& slotEdge(const Rule& r, const NegativeCondition* nac, int i) {
    return i < static_cast<int>(r.edges.size()) ? r.edges[i] : nac->edges[i - nac->outerEdges];
}

struct Program {
    std::vector<Enum> enums;
    std::vector<Kind> kinds;
    std::vector<Param> params;
    std::vector<Const> consts;
    std::vector<Function> functions;
    Axiom axiom;
    std::optional<Expr> stepLimit;
    std::map<long long, PriorityConfig> priorities;
    std::vector<std::string> svgDefs;
    std::vector<Rule> rules;
    // Every style property a per-element assignment sets, in order of first
    // use: the runtime numbers them in this order (rt::StyleStore).
    std::vector<std::string> styleProps;
};

std::string typeName(const Type& t, const Program& p);

}  // namespace g2d::ir
