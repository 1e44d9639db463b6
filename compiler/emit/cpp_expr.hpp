#pragma once
// Generates C++ for IR expressions. Every subexpression lands in its own
// temporary, in evaluation order, so random draws and errors happen exactly
// as in the interpreter (C++ leaves the order of operands unspecified).
#include <functional>
#include <string>
#include <vector>

#include "ir/ir.hpp"

namespace g2d::emit {

// The source places of run-time errors, numbered for the generated table.
class Places {
public:
    int add(const Span& s);
    const std::vector<Span>& all() const { return spans_; }

private:
    std::vector<Span> spans_;
};

// Literal style values, each built once with the grammar (a `const Value`
// member) rather than per rewrite: a daughter that sets `style.tag = "none"`
// on twenty elements copies one constant twenty times, with no string
// built, kept and converted per element.
class ConstantValues {
public:
    // The C++ name of the constant holding `valueExpr` (a Value's
    // initialiser), shared by equal ones.
    std::string add(const std::string& valueExpr);
    // Their declarations as members of the grammar's class, in order.
    std::string definitions() const;

private:
    std::vector<std::string> exprs_;
};

std::string cppType(const ir::Type& t);
std::string cppLiteral(const ir::Value& v, const ir::Type& t);
std::string cppString(const std::string& s);
// A style property by its number (the graph numbers ir::Program::styleProps
// in order), with its name in a comment.
std::string cppStyleProp(const ir::StyleAssign& s);
// A runtime Value holding C++ expression `v` of type `t` (enums as
// EnumVal): its brace initialiser, and the Value itself.
std::string valueInit(const ir::Type& t, const std::string& v);
std::string valueOf(const ir::Type& t, const std::string& v);

// How an expression reaches what it reads; set per context.
struct ExprContext {
    std::function<std::string(int)> node;       // host id of pattern node i
    std::function<std::string(int)> edge;       // host id of pattern edge i
    std::function<int(int)> nodeKind;           // kind of pattern node i
    std::function<int(int)> edgeKind;           // kind of pattern edge i
    std::function<std::string(int)> face;       // host id of pattern face i
    std::function<int(int)> faceKind;           // kind of pattern face i
    std::string self;                           // host id of the styled element
    ir::ElemClass selfClass = ir::ElemClass::Node;
    int selfKind = -1;
    std::string graph = "g";                    // the graph read
};

class ExprGen {
public:
    ExprGen(const ir::Program& prog, Places& places) : prog_(prog), places_(places) {}

    // Appends statements computing `e` to `out` (each line prefixed by
    // `indent`) and returns the C++ expression that names its value.
    std::string gen(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& indent);

    // C++ that reads attribute `attr` of a node or edge of kind `kind`.
    std::string attrAccess(int kind, const std::string& id, ir::ElemClass cls, int attr, const std::string& graph) const;

private:
    std::string temp() { return "t" + std::to_string(next_++); }
    std::string place(const ir::Expr& e, std::string& out, const std::string& indent);
    std::string call(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& indent);
    std::string binary(const ir::Expr& e, const ExprContext& ctx, std::string& out, const std::string& indent);
    std::string fact(const ir::Expr& e, const std::string& id, ir::ElemClass cls, const std::string& graph);
    std::string display(const std::string& value, const ir::Type& t);

    const ir::Program& prog_;
    Places& places_;
    int next_ = 0;
};

}  // namespace g2d::emit
