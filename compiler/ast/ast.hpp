#pragma once
// The abstract syntax tree: our own plain types, built from the ANTLR parse
// tree by compiler/parse and read by compiler/sema. Nothing here knows ANTLR.
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "diag/source.hpp"

namespace g2d::ast {

struct Ident {
    std::string name;
    Span span;
};

// ---- expressions -----------------------------------------------------------
struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

enum class UnaryOp { Neg, Plus, Not };
enum class BinaryOp { Add, Sub, Mul, Div, Mod, Lt, Le, Gt, Ge, Eq, Ne, And, Or };

struct IntLit { long long value; bool overflow = false; };
struct FloatLit { double value; };
struct StringLit { std::string value; };
struct BoolLit { bool value; };
struct Name { std::string name; };
struct Member { ExprPtr object; Ident member; };
struct Call { Ident callee; std::vector<ExprPtr> args; };
struct VecLit { ExprPtr x, y, z; };   // z: a vec3
struct Unary { UnaryOp op; ExprPtr operand; };
struct Binary { BinaryOp op; ExprPtr lhs, rhs; Span opSpan; };
struct Conditional { ExprPtr cond, then, otherwise; };

struct Expr {
    Span span;
    std::variant<IntLit, FloatLit, StringLit, BoolLit, Name, Member, Call, VecLit, Unary, Binary,
                 Conditional> node;
};

struct TypeRef {
    Ident name;
};

// ---- graphs ----------------------------------------------------------------
struct Assignment {
    bool isStyle = false;     // `style.NAME = expr`
    Ident name;
    ExprPtr value;
};

struct Sketch {
    double x = 0, y = 0;
    Span span;
};

// `name: Kind @ (x, y) at expr { a = 1 } where cond;`
struct NodeStmt {
    Ident name;
    std::optional<Ident> kind;      // absent: refers to an existing element
    bool wildcard = false;          // `name: *`
    Span kindSpan;
    std::optional<Sketch> sketch;
    ExprPtr position;               // `at expr`
    std::vector<Assignment> assigns;
    bool hasAssignBlock = false;
    ExprPtr where;
    Span span;
};

// `name: a -[Kind {..}]-> b where cond;`
struct EdgeStmt {
    std::optional<Ident> name;
    Ident src, dst;
    Ident kind;
    enum class Arrow { Forward, Backward, Undirected } arrow = Arrow::Forward;
    std::vector<Assignment> assigns;
    ExprPtr where;
    Span span;
};

// `all t` or `all t reversed` as a face's corners: node t of every turn of
// a `for` loop (`every` and `order` are the words as written; sema checks them).
struct RingCorners {
    Ident every, node;
    std::optional<Ident> order;
    Span span;
};

// `name: Kind(a, b, c) {..} where cond;` a face and its corners, in order.
struct FaceStmt {
    std::optional<Ident> name;
    Ident kind;
    std::vector<Ident> corners;
    std::optional<RingCorners> ring;   // `Kind(all t)`: then no corners
    std::vector<Assignment> assigns;
    ExprPtr where;
    Span span;
};

struct GraphStmt {
    std::variant<NodeStmt, EdgeStmt, FaceStmt> stmt;
};

struct MatchStmt;
struct WhereStmt { ExprPtr cond; Span span; };
struct NacBlock { std::vector<MatchStmt> body; Span span; };
struct MatchStmt {
    std::variant<GraphStmt, WhereStmt, NacBlock> stmt;
};

struct LetStmt {
    Ident name;
    std::optional<TypeRef> type;
    ExprPtr value;
    Span span;
};

struct ProduceStmt;
// `for (u, v) in f.sides { … }` or `for c in f.corners { … }` in a daughter.
struct ForBlock {
    std::vector<Ident> vars;           // (u, v), or c
    Ident face;
    Ident what;                        // `sides` or `corners`
    std::vector<ProduceStmt> body;
    Span span;
};
// `insert m between a and b;` in a daughter: G^3's Split edge on faces.
struct InsertStmt {
    Ident node, first, second;
    Span span;
};
// `split f [around Kind at POS {…}] with EdgeKind {…} [for c in f.corners
// where COND];` in a daughter: G^3's Split face.
struct SplitStmt {
    struct Centre {
        Ident kind;
        ExprPtr position;
        std::vector<Assignment> assigns;
        Span span;
    };
    Ident face;
    std::optional<Centre> centre;
    Ident edgeKind;
    std::vector<Assignment> edgeAssigns;
    std::optional<Ident> var;          // the corner, with loopFace.what and cond
    Ident loopFace, what;
    ExprPtr cond;
    Span span;
};
struct ProduceStmt {
    std::variant<LetStmt, GraphStmt, ForBlock, InsertStmt, SplitStmt> stmt;
};

struct ProduceBlock {
    ExprPtr weight;                 // absent: 1
    std::vector<ProduceStmt> body;
    Span span;
};

struct RuleItem {
    std::variant<LetStmt, ProduceBlock> item;
};

struct RuleOption {
    enum class Kind { Priority, Pick, Ordered, Parallel, Word, Weight, Limit } kind;
    long long priority = 0;
    bool priorityOverflow = false;
    Ident pick;
    Ident pickMeasure;              // `pick oldest generation`: empty when not written
    Ident word;                     // Word: an option named by a plain name (`merge`)
    ExprPtr weight;                 // Weight: `weight W`
    ExprPtr limit;                  // Limit: `limit N`
    Span span;
};

struct RuleDecl {
    Ident name;
    bool compoundMatch = false;        // a compound's match (CompoundDecl): its lets are the compound's values
    std::vector<RuleOption> options;
    std::vector<MatchStmt> match;
    Span matchSpan;
    std::vector<RuleItem> items;
    Span span;
};

// ---- declarations ----------------------------------------------------------
struct SpaceDecl { int dimensions = 2; Span span; };
struct ImportDecl { std::string path; Span span; };
// `in LOWER..UPPER [step STEP]` after a parameter's default (`step` is a
// plain name: sema checks the word).
struct ParamRange { ExprPtr lower, upper; std::optional<Ident> stepWord; ExprPtr step; Span span; };
struct ParamDecl { Ident name; TypeRef type; ExprPtr value; Span span; std::optional<ParamRange> range; };
struct ConstDecl { Ident name; std::optional<TypeRef> type; ExprPtr value; Span span; };
struct EnumDecl { Ident name; std::vector<Ident> values; Span span; };
struct FnParam { Ident name; TypeRef type; };
struct FnDecl { Ident name; std::vector<FnParam> params; TypeRef result; ExprPtr body; Span span; };

struct AttrDecl { Ident name; TypeRef type; ExprPtr value; Span span; };
struct StyleProp { Ident name; ExprPtr value; Span span; };
struct KindDecl {
    enum class Class { Node, Edge, Face } cls = Class::Node;
    std::optional<bool> directed;   // edges: `directed` / `undirected` / unspecified
    std::optional<Ident> option;    // faces: the word after the name (`oriented`)
    Ident name;
    std::vector<AttrDecl> attrs;
    std::vector<StyleProp> style;
    std::vector<StyleProp> layout;  // edges: `layout { angle = …; … }` (the drawing step's)
    bool hasLayout = false;
    Span span;
};

struct AxiomDecl { std::vector<GraphStmt> body; Span span; };
struct LimitDecl { ExprPtr value; Span span; };
struct PriorityDecl {
    long long priority = 0;
    bool priorityOverflow = false;
    Span prioritySpan;
    ExprPtr limit;
    bool parallel = false;
    bool generation = false;            // `generation`: every rule of the priority rewrites all its matches in one step
    std::vector<Ident> unknownOptions;  // words that are no option
    std::vector<Span> repeatedOptions;  // an option given twice
    Span span;
};
struct DefsDecl { std::string svg; Span span; };
struct MergeDecl { ExprPtr tolerance; Span span; };
// An entry of a command list: a name (a rule, compound or named list), or
// `repeat COUNT { … }` (count set, its entries in body).
struct SequenceItem {
    Ident name;
    ExprPtr count;
    std::vector<SequenceItem> body;
    Span span;
};
// `sequence { … }`, or a named list `sequence NAME { … }` (G^3's rule, §2.4.6).
struct SequenceDecl { std::optional<Ident> name; std::vector<SequenceItem> items; Span span; };
// `compound C { match { … } let …; sequence { … } }`: `match` is a rule named
// C, with the compound's lets, whose one daughter is empty (it is never
// applied: its matches are the compound's initial primitives).
struct CompoundDecl { RuleDecl match; SequenceDecl body; Span span; };
// `layout angles { canvas_min = …; … }`
struct LayoutDecl { Ident name; std::vector<StyleProp> props; Span span; };
// `canvas LOWER to UPPER;` (`canvas` and `to` are plain names: sema checks `to`)
struct CanvasDecl { ExprPtr lower; Ident to; ExprPtr upper; Span span; };

struct Decl {
    std::variant<SpaceDecl, ImportDecl, ParamDecl, ConstDecl, EnumDecl, FnDecl, KindDecl, AxiomDecl, LimitDecl,
                 PriorityDecl, DefsDecl, MergeDecl, SequenceDecl, CompoundDecl, LayoutDecl, CanvasDecl, RuleDecl> decl;
};

// One parsed file.
struct Program {
    FileId file = kNoFile;
    std::vector<Decl> decls;
};

}  // namespace g2d::ast
