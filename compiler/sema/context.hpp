#pragma once
// State shared by the semantic passes: the IR being built, global symbol
// tables, and the environment an expression is checked in.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ast/ast.hpp"
#include "diag/diagnostic.hpp"
#include "ir/ir.hpp"

namespace g2d::sema {

struct Globals {
    Globals(ir::Program& p, Diagnostics& d) : prog(p), diags(d) {}
    ir::Program& prog;
    Diagnostics& diags;
    FileId mainFile = kNoFile;                  // warnings about unused names only there

    std::map<std::string, Span> topLevel;       // every top-level name, for duplicates
    std::map<std::string, int> kinds, enums, params, consts, functions;
    std::map<std::string, std::vector<ir::EnumValue>> enumerators;  // bare enumerator names
    std::vector<bool> paramUsed, constUsed;
    std::vector<FileId> paramFile, constFile;
    int constsDeclared = 0;                     // consts visible so far (declaration order)
    int functionsDeclared = 0;                  // functions visible so far (no recursion)
    std::vector<int> functionDepth;             // per function: calls nested in it, itself included
    bool tooManyKinds = false;                  // reported once
    std::map<std::string, int> styleProps;      // style property -> its number (ir::Program::styleProps)
    bool tooManyStyleProps = false;             // reported once
    // Values and functions declared anywhere, for "used before its declaration".
    std::map<std::string, Span> laterValues, laterFunctions;
    std::string definingConst;                  // the constant whose value is being checked
    std::map<std::string, int> compounds;       // compound name -> index (its lets are readable as C.name)
    bool layoutDeclared = false;                // a `layout …` declaration, even a bad one
    // Per rule (by index), the compounds whose lets it reads, with a place (it must run within them).
    std::map<int, std::map<int, Span>> compoundReads;

    std::string typeName(const ir::Type& t) const { return ir::typeName(t, prog); }
};

struct LocalVar {
    std::string name;
    ir::Type type;
    int slot = -1;
    bool isFnArg = false;
    Span span;
    bool used = false;
};

struct ElemBinding {
    std::string name;
    ir::ElemRef ref;
    int kind = -1;                   // -1: wildcard
    Span span;
    std::string unreadable;          // non-empty: why expressions may not read it
    bool poisoned = false;           // its declaration failed (reported); uses stay silent
};

// Where an expression sits decides what it may use.
struct ExprEnv {
    std::string context;             // "a match condition", "a weight", ... for messages
    bool allowRandom = true;
    bool allowElements = true;
    bool allowLocals = true;
    int selfKind = -1;               // style expressions: bare names read the element's attributes
    int placedNode = -1;             // `at` of a new sketched node: `placed` is its automatic position
    bool compoundValues = false;     // a rule's expression: `C.name` reads compound C's let
    bool counts = false;             // `layout angles`' cost: `count(K)`, `nodes` and `edges`
    std::vector<LocalVar>* locals = nullptr;      // searched from the back (inner scopes last)
    const std::vector<ElemBinding>* elems = nullptr;
    std::set<ir::ElemRef>* deps = nullptr;        // collects the elements read
};

}  // namespace g2d::sema
