#include "emit/cpp_emitter.hpp"

#include <functional>

#include "emit/cpp_angle_layout.hpp"
#include "emit/cpp_expr.hpp"
#include "emit/cpp_rewrite.hpp"
#include "emit/cpp_rules.hpp"
#include "lower/command_lists.hpp"
#include "lower/start_program.hpp"
#include "lower/rule_facts.hpp"

#include <algorithm>

namespace g2d::emit {

namespace {

std::string str(long long i) { return std::to_string(i); }

// A C string literal (the source has no NUL bytes: the loader rejects them).
std::string cLiteral(const std::string& s) {
    std::string lit = cppString(s);                       // std::string("...", n)
    return lit.substr(12, lit.rfind("\", ") - 12 + 1);   // "..."
}

// `std::vector<int>{a, b}` or `std::vector<long long>{aLL, bLL}` (typed, so
// that an empty list stays a vector).
template <class T>
std::string vectorLiteral(const std::vector<T>& v) {
    constexpr bool wide = sizeof(T) > sizeof(int);
    std::string out = wide ? "std::vector<long long>{" : "std::vector<int>{";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + str(v[i]) + (wide ? "LL" : "");
    return out + "}";
}

std::string incidenceName(rt::Incidence r) {
    switch (r) {
    case rt::Incidence::None: return "Incidence::None";
    case rt::Incidence::PatternEdges: return "Incidence::PatternEdges";
    case rt::Incidence::AllEdges: return "Incidence::AllEdges";
    }
    return "Incidence::AllEdges";
}

template <class T>
std::string listOf(const std::vector<T>& v, std::string (*item)(T)) {
    std::string out = "{";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + item(v[i]);
    return out + "}";
}
std::string byteText(std::uint8_t b) { return std::to_string(static_cast<int>(b)); }

// `RuleInfo info` as the lowering made it (lower::ruleFacts), field by field:
// the generated grammar holds the same data the interpreter computes.
std::string ruleInfo(const rt::RuleInfo& i, const std::string& in) {
    std::string out = in + "RuleInfo info;\n";
    out += in + "info.name = " + cppString(i.name) + ";\n";
    out += in + "info.priority = " + cppLiteral(ir::Value{i.priority}, ir::kIntType) + ";\n";
    out += in + "info.pick = " + (i.pick == rt::Pick::OldestGeneration ? "Pick::OldestGeneration"
                                  : i.pick == rt::Pick::Oldest          ? "Pick::Oldest"
                                                                        : "Pick::Random") + ";\n";
    out += in + "info.parallel = " + (i.parallel ? "true" : "false") + ";\n";
    if (i.matchWeighted) out += in + "info.matchWeighted = true;\n";
    out += in + "info.generation = " + (i.generation ? "true" : "false") + ";\n";
    out += in + "info.weights = {";
    for (std::size_t d = 0; d < i.weights.size(); ++d) out += (d ? ", " : "") + cppLiteral(ir::Value{i.weights[d]}, ir::kFloatType);
    out += "};\n";
    if (i.choiceWeight != 1) out += in + "info.choiceWeight = " + cppLiteral(ir::Value{i.choiceWeight}, ir::kFloatType) + ";\n";
    out += in + "info.radius = " + str(i.radius) + ";\n";
    out += in + "info.nearKinds = " + vectorLiteral(i.nearKinds) + ";\n";
    if (!i.joinKinds.empty()) out += in + "info.joinKinds = " + vectorLiteral(i.joinKinds) + ";\n";
    out += in + "info.readsIncidence = " + listOf(i.readsIncidence, incidenceName) + ";\n";
    out += in + "info.readDirections = " + listOf(i.readDirections, byteText) + ";\n";
    out += in + "info.newHostAddsNothing = " + listOf(i.newHostAddsNothing, byteText) + ";\n";
    out += in + "info.edgeCount = " + str(i.edgeCount) + ";\n";
    out += in + "info.faceCount = " + str(i.faceCount) + ";\n";
    out += in + "info.nodeKinds = " + vectorLiteral(i.nodeKinds) + ";\n";
    out += in + "info.kindsKnown = " + (i.kindsKnown ? "true" : "false") + ";\n";
    out += in + "info.readKinds = " + vectorLiteral(i.readKinds) + ";\n";
    out += in + "info.readsDegrees = " + (i.readsDegrees ? "true" : "false") + ";\n";
    out += in + "info.readsNeighbours = " + (i.readsNeighbours ? "true" : "false") + ";\n";
    out += in + "info.readValues = " + vectorLiteral(i.readValues) + ";\n";
    for (std::size_t d = 0; d < i.changedKinds.size(); ++d) {
        out += in + "info.changedKinds.push_back(" + vectorLiteral(i.changedKinds[d]) + ");\n";
        out += in + "info.changedValues.push_back(" + vectorLiteral(i.changedValues[d]) + ");\n";
    }
    out += in + "info.deletesNodes = " + listOf(i.deletesNodes, byteText) + ";\n";
    if (i.mergeTolerance > 0) out += in + "info.mergeTolerance = " + cppLiteral(ir::Value{i.mergeTolerance}, ir::kFloatType) + ";\n";
    if (!i.globalMatches) out += in + "info.globalMatches = false;\n";
    if (i.intersect) out += in + "info.intersect = true;\n";
    out += daughterShapesText(i.shapes, in);
    return out;
}

std::string paramType(const ir::Type& t) {
    switch (t.kind) {
    case ir::TypeKind::Int: return "ParamType::Int";
    case ir::TypeKind::Float: return "ParamType::Float";
    case ir::TypeKind::Bool: return "ParamType::Bool";
    case ir::TypeKind::Vec2: return "ParamType::Vec2";
    case ir::TypeKind::Vec3: return "ParamType::Vec3";
    case ir::TypeKind::Enum: return "ParamType::Enum";
    default: return "ParamType::String";
    }
}

// Reads a parameter value from the driver's Value.
std::string fromValue(const ir::Type& t, const std::string& v) {
    if (t.kind == ir::TypeKind::Enum) return "std::get<EnumVal>(" + v + ").index";
    return "std::get<" + cppType(t) + ">(" + v + ")";
}

class ProgramEmitter {
public:
    ProgramEmitter(const ir::Program& prog, const EmitOptions& options)
        : prog_(prog), options_(options), gen_(prog, places_) {}

    std::string emit() {
        std::string functions = emitFunctions();
        std::string start = emitStart();
        std::string limits = emitLimits();
        std::string canvas = emitCanvas();
        std::string rules;
        int firstDaughter = 0;
        for (std::size_t r = 0; r < prog_.rules.size(); ++r) {
            rules += emitRule(prog_, prog_.rules[r], static_cast<int>(r), firstDaughter, gen_, places_, constants_);
            firstDaughter += static_cast<int>(prog_.rules[r].daughters.size());
        }
        std::string styles = emitStyles();

        std::string out;
        out += "// Generated by g2d from " + options_.grammarFile + ". Do not edit.\n";
        out += "#include <g2d/compiled.hpp>\n\n#include <algorithm>\n#include <iterator>\n\nnamespace {\n\n";
        out += "namespace rt = g2d::rt;\nnamespace rtc = g2d::rt::compiled;\nusing namespace g2d::rt;\nusing namespace g2d::rt::compiled;\n\n";
        out += emitEnums() + emitKinds() + emitParamsConsts() + emitPlaces();
        out += "class Grammar final : public GrammarRun, public RuleSet {\npublic:\n";
        out += emitConstructor();
        out += "    const std::vector<ParamSpec>& params() const override { return specs_; }\n";
        out += "    Graph& graph() override { return graph_; }\n    RuleSet& rules() override { return *this; }\n";
        out += "    const std::vector<std::string>& svgDefs() const override { return defs_; }\n";
        out += "    const JsonSchema& jsonSchema() const override { return schema_; }\n";
        out += "    std::string currentRule() const override { return std::string(current_); }\n";
        out += "    std::optional<SourceLocation> locate(const std::exception& e) const override {\n"
               "        const auto* p = dynamic_cast<const PlacedError*>(&e);\n"
               "        if (!p || p->place < 0) return std::nullopt;\n"
               "        const Place& at = kPlaces[p->place];\n"
               "        return SourceLocation{at.file, at.line, at.col, at.endCol, at.lineText};\n    }\n\n";
        out += start + limits + canvas + emitRuleSet() + emitSequenceAndCopies() + emitAttribute() + styles;
        out += "private:\n" + functions + rules + emitMembers() + "};\n\n}  // namespace\n\n";
        out += "std::unique_ptr<g2d::rt::GrammarRun> " + options_.factoryName + "();\n";
        out += "std::unique_ptr<g2d::rt::GrammarRun> " + options_.factoryName + "() { return std::make_unique<Grammar>(); }\n";
        if (options_.withMain)
            out += "\nint main(int argc, char** argv) {\n    Grammar grammar;\n    RunRequest request;\n"
                   "    if (auto code = parseRunArguments(argc, argv, " + cLiteral(options_.grammarFile) +
                   ", grammar.params(), request)) return *code;\n    return runGrammar(request, grammar);\n}\n";
        return out;
    }

private:
    std::string emitEnums() {
        std::string out;
        for (std::size_t e = 0; e < prog_.enums.size(); ++e) {
            out += "const char* const enum_names_" + str(static_cast<long long>(e)) + "[] = {";
            for (std::size_t v = 0; v < prog_.enums[e].values.size(); ++v)
                out += (v ? ", " : "") + cLiteral(prog_.enums[e].values[v]);
            out += "};\n";
        }
        out += "const char* const* const enum_tables[] = {";
        for (std::size_t e = 0; e < prog_.enums.size(); ++e) out += (e ? ", " : "") + std::string("enum_names_") + str(static_cast<long long>(e));
        if (prog_.enums.empty()) out += "nullptr";
        return out + "};\n\n";
    }

    std::string emitKinds() {
        std::string out;
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            const auto& kind = prog_.kinds[k];
            if (kind.attrs.empty()) continue;
            out += "struct Kind" + str(static_cast<long long>(k)) + " {  // " + rt::elemClassName(kind.cls) + " " + kind.name + "\n";
            for (std::size_t a = 0; a < kind.attrs.size(); ++a)
                out += "    " + cppType(kind.attrs[a].type) + " a" + str(static_cast<long long>(a)) + "{};  // " + kind.attrs[a].name + "\n";
            out += "};\n";
        }
        return out + "\n";
    }

    std::string emitParamsConsts() {
        std::string out = "struct Params {\n";
        for (std::size_t i = 0; i < prog_.params.size(); ++i)
            out += "    " + cppType(prog_.params[i].type) + " p" + str(static_cast<long long>(i)) + "{};  // " + prog_.params[i].name + "\n";
        out += "};\nstruct Consts {\n";
        for (std::size_t i = 0; i < prog_.consts.size(); ++i)
            out += "    " + cppType(prog_.consts[i].type) + " c" + str(static_cast<long long>(i)) + "{};  // " + prog_.consts[i].name + "\n";
        return out + "};\n\n";
    }

    std::string emitPlaces() {
        std::string out = "const Place kPlaces[] = {\n";
        for (const auto& s : places_.all()) {
            std::string file, line;
            if (options_.sources && s.file < options_.sources->size()) {
                file = options_.sources->file(s.file).path;
                line = options_.sources->lineText(s.file, s.line);
            }
            const unsigned end = s.endLine == s.line ? s.endCol : 0;
            out += "    {" + cLiteral(file) + ", " + str(s.line) + ", " + str(s.col) + ", " + str(end) + ", " + cLiteral(line) + "},\n";
        }
        if (places_.all().empty()) out += "    {\"\", 0, 0, 0, \"\"},\n";
        return out + "};\n\n";
    }

    std::string emitConstructor() {
        std::string out = "    Grammar() : graph_(std::vector<KindInfo>{";
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k)
            out += (k ? ", " : "") + std::string("KindInfo{") + (prog_.kinds[k].cls == ir::ElemClass::Edge ? "ElemClass::Edge" : prog_.kinds[k].cls == ir::ElemClass::Face ? "ElemClass::Face" : "ElemClass::Node") +
                   ", " + (prog_.kinds[k].directed ? "true" : "false") + "}";
        out += "}, std::vector<std::string>{";
        for (std::size_t i = 0; i < prog_.styleProps.size(); ++i) out += (i ? ", " : "") + cppString(prog_.styleProps[i]);
        out += "}) {\n";
        for (const auto& p : prog_.params) {
            out += "        specs_.push_back(ParamSpec{" + cLiteral(p.name) + ", " + cLiteral(ir::typeName(p.type, prog_)) + ", " +
                   paramType(p.type) + ", " + str(p.type.enumId) + ", {";
            if (p.type.kind == ir::TypeKind::Enum)
                for (std::size_t v = 0; v < prog_.enums[p.type.enumId].values.size(); ++v)
                    out += (v ? ", " : "") + cLiteral(prog_.enums[p.type.enumId].values[v]);
            out += "}, " + valueOf(p.type, cppLiteral(p.defaultValue, p.type)) + "});\n";
        }
        if (prog_.space3d) out += "        schema_.space3d = true;\n";
        for (const auto& k : prog_.kinds) {
            out += "        schema_.kindNames.push_back(" + cLiteral(k.name) + ");\n        schema_.attrNames.push_back({";
            for (std::size_t a = 0; a < k.attrs.size(); ++a) out += (a ? ", " : "") + cLiteral(k.attrs[a].name);
            out += "});\n";
        }
        for (const auto& e : prog_.enums) {
            out += "        schema_.enumValueNames.push_back({";
            for (std::size_t v = 0; v < e.values.size(); ++v) out += (v ? ", " : "") + cLiteral(e.values[v]);
            out += "});\n";
        }
        for (const auto& d : prog_.svgDefs) out += "        defs_.push_back(" + cppString(d) + ");\n";
        return out + "    }\n\n";
    }

    std::string emitFunctions() {
        std::string out;
        ExprContext ctx;
        for (std::size_t i = 0; i < prog_.functions.size(); ++i) {
            const auto& fn = prog_.functions[i];
            out += "    " + cppType(fn.result) + " fn_" + str(static_cast<long long>(i)) + "(";
            for (std::size_t a = 0; a < fn.paramTypes.size(); ++a)
                out += (a ? ", " : "") + cppType(fn.paramTypes[a]) + " a" + str(static_cast<long long>(a));
            out += ") {  // " + fn.name + "\n";
            out += "        rt::checkDeadline();\n";
            const std::string v = gen_.gen(fn.body, ctx, out, "        ");
            out += "        return " + v + ";\n    }\n\n";
        }
        return out;
    }

    ExprContext noElements() const { return ExprContext{}; }
    // The elements of a match `m` of rule r, as a view (RuleSet::weigh, compoundValues).
    static ExprContext matchElements(const ir::Rule& r) {
        ExprContext ctx;
        ctx.node = [](int i) { return "m.nodes[" + str(i) + "]"; };
        ctx.edge = [](int i) { return "m.edges[" + str(i) + "]"; };
        ctx.face = [](int i) { return "m.faces[" + str(i) + "]"; };
        ctx.nodeKind = [&r](int i) { return r.nodes[static_cast<std::size_t>(i)].kind; };
        ctx.edgeKind = [&r](int i) { return r.edges[static_cast<std::size_t>(i)].kind; };
        ctx.faceKind = [&r](int i) { return r.faces[static_cast<std::size_t>(i)].kind; };
        return ctx;
    }

    std::string emitStart() {
        const std::string in = "            ";
        std::string out = "    void start(const std::vector<Value>& params, Rng& rng) override {\n";
        out += "        (void)params;\n        rng_ = &rng;\n        current_ = \"\";\n        clearPending();\n        try {\n";
        for (std::size_t i = 0; i < prog_.params.size(); ++i)
            out += in + "P_.p" + str(static_cast<long long>(i)) + " = " + fromValue(prog_.params[i].type, "params[" + str(static_cast<long long>(i)) + "]") + ";\n";
        const lower::StartProgram start = lower::lowerStart(prog_);
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k)
            if (!prog_.kinds[k].attrs.empty())
                out += in + "default_" + str(static_cast<long long>(k)) + " = Kind" + str(static_cast<long long>(k)) + "{};\n";
        for (const auto& op : start.init) {
            std::visit(lower::Overloaded{
                           [&](const lower::InitConst& o) {
                               const auto& c = *o.decl;
                               const std::string v = c.folded ? cppLiteral(*c.folded, c.type) : gen_.gen(c.value, noElements(), out, in);
                               out += in + "C_.c" + str(o.index) + " = " + v + ";\n";
                           },
                           [&](const lower::InitDefault& o) {
                               const std::string v = gen_.gen(*o.value, noElements(), out, in);
                               out += in + "default_" + str(o.kind) + ".a" + str(o.attr) + " = " + v + ";\n";
                           },
                       },
                       op);
        }
        out += in + "graph_ = Graph(graph_.kinds(), graph_.styleProps());\n";
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k)
            if (!prog_.kinds[k].attrs.empty()) out += in + "store_" + str(static_cast<long long>(k)) + ".clear();\n";
        // The axiom: a rewrite of the empty graph at step 0.
        RewritePrinter axiom(prog_, gen_, places_, constants_);
        out += in + "{\n" + in + "    Graph& G = graph_;\n" + in + "    const long long step = 0;\n" + in + "    const Match m{};\n" + in + "    (void)m;\n";
        out += axiom.prepare(start.axiom, noElements(), in + "    ") + axiom.commit(start.axiom, in + "    ") + in + "}\n";
        // Rule infos, with weights (parameter-dependent ones checked now).
        out += in + "infos_.clear();\n";
        if (prog_.tracksGenerations) out += in + "tracksGenerations = true;\n";
        for (const auto& r : prog_.rules) {
            const lower::RuleFacts facts = lower::ruleFacts(prog_, r);
            out += in + "{\n" + ruleInfo(facts.info, in + "    ");
            // `target = check(expr);`, a failure placed at the expression.
            auto checked = [&](const ir::Expr& expr, const std::string& target, const std::string& check) {
                const std::string v = gen_.gen(expr, noElements(), out, in + "    ");
                out += in + "    try {\n" + in + "        " + target + " = " + check + "(" + v + ");\n" + in +
                       "    } catch (const OpError& e) {\n" + in + "        throw PlacedError(" + str(places_.add(expr.span)) + ", e.what());\n" + in + "    }\n";
            };
            for (std::size_t d = 0; d < facts.weightExprs.size(); ++d)
                if (const ir::Expr* expr = facts.weightExprs[d]) checked(*expr, "info.weights[" + str(static_cast<long long>(d)) + "]", "checkedWeight");
            if (const ir::Expr* expr = facts.choiceWeightExpr) checked(*expr, "info.choiceWeight", "checkedWeight");
            if (const ir::Expr* expr = facts.mergeExpr) checked(*expr, "info.mergeTolerance", "checkedMergeTolerance");
            out += in + "    infos_.push_back(std::move(info));\n" + in + "}\n";
        }
        out += "        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n    }\n\n";
        return out;
    }

    std::string emitLimits() {
        std::string out = "    std::optional<long long> stepLimit() override {\n";
        if (!prog_.stepLimit) {
            out += "        return std::nullopt;\n    }\n\n";
        } else {
            out += "        try {\n";
            const std::string v = gen_.gen(*prog_.stepLimit, noElements(), out, "            ");
            out += "            return " + v + ";\n        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n    }\n\n";
        }
        out += "    std::map<long long, long long> priorityLimits() override {\n        std::map<long long, long long> out;\n        try {\n";
        for (const auto& [prio, cfg] : prog_.priorities) {
            if (!cfg.limit) continue;
            const std::string v = gen_.gen(*cfg.limit, noElements(), out, "            ");
            out += "            out[" + cppLiteral(ir::Value{prio}, ir::kIntType) + "] = " + v + ";\n";
        }
        out += "        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n        return out;\n    }\n\n";
        return out;
    }

    // The grammar's `canvas`, checked where its declaration stands (as the interpreter does).
    std::string emitCanvas() {
        std::string out = "    std::optional<ViewBox> canvas() override {\n";
        if (!prog_.canvas) return out + "        return std::nullopt;\n    }\n\n";
        out += "        try {\n";
        const std::string lower = gen_.gen(prog_.canvas->lower, noElements(), out, "            ");
        const std::string upper = gen_.gen(prog_.canvas->upper, noElements(), out, "            ");
        out += "            loc_ = " + str(places_.add(prog_.canvas->span)) + ";\n";
        out += "            return checkedCanvas(" + lower + ", " + upper + ");\n";
        return out + "        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n    }\n\n";
    }

    // `layout angles`' cost and temperature (RuleSet::drawingCost), checked as the interpreter does.
    std::string emitDrawingCost() {
        if (!prog_.angleLayout || !prog_.angleLayout->cost) return "";
        auto checked = [&](const ir::Expr& expr, const std::string& check) {
            std::string out = "        try {\n";
            const std::string v = gen_.gen(expr, noElements(), out, "            ");
            return out + "            return " + check + "(" + v + ");\n        } catch (const OpError& e) {\n            throw PlacedError(" +
                   str(places_.add(expr.span)) + ", e.what());\n        }\n    }\n\n";
        };
        std::string out = "    bool hasDrawingCost() const override { return true; }\n\n";
        out += "    double drawingCost(const KindCounts& counts) override {\n        (void)counts;\n";
        out += checked(*prog_.angleLayout->cost, "checkedCost");
        if (const auto& t = prog_.angleLayout->temperature) out += "    double drawingTemperature() override {\n" + checked(*t, "checkedTemperature");
        return out;
    }

    // Weights that read the match, per application (RuleSet::weigh).
    std::string emitWeigh() {
        std::string out, cases;
        for (std::size_t r = 0; r < prog_.rules.size(); ++r) {
            const ir::Rule& rule = prog_.rules[r];
            const lower::RuleFacts facts = lower::ruleFacts(prog_, rule);
            if (!facts.info.matchWeighted) continue;
            const std::string rs = str(static_cast<long long>(r));
            const ExprContext ctx = matchElements(rule);
            out += "    void weigh_" + rs + "(Match m, const Graph& g, std::vector<double>& w) {\n        (void)m;\n        (void)g;\n";
            int first = -1;
            for (std::size_t d = 0; d < facts.matchWeightExprs.size(); ++d) {
                const ir::Expr* expr = facts.matchWeightExprs[d];
                if (!expr) continue;
                const int place = places_.add(expr->span);
                first = first < 0 ? place : first;
                out += "        try {\n";
                const std::string v = gen_.gen(*expr, ctx, out, "            ");
                out += "            w[" + str(static_cast<long long>(d)) + "] = checkedMatchWeight(" + v + ");\n";
                out += "        } catch (const OpError& e) {\n            throw PlacedError(" + str(place) + ", e.what());\n        }\n";
            }
            out += "        try {\n            checkSomeWeight(w);\n        } catch (const OpError& e) {\n            throw PlacedError(" +
                   str(first) + ", e.what());\n        }\n    }\n\n";
            cases += "        case " + rs + ": weigh_" + rs + "(m, g, w); break;\n";
        }
        if (cases.empty()) return out;
        out += "    void weigh(std::size_t rule, Match m, const Graph& g, std::vector<double>& w) override {\n"
               "        current_ = infos_[rule].name.c_str();\n        switch (rule) {\n" + cases + "        default: break;\n        }\n    }\n\n";
        return out;
    }

    std::string emitRuleSet() {
        const std::size_t n = prog_.rules.size();
        std::string names = "        static const char* const names[] = {";
        for (std::size_t r = 0; r < n; ++r) names += (r ? ", " : "") + cLiteral(prog_.rules[r].name);
        if (n == 0) names += "\"\"";
        names += "};\n";
        std::string out = "    std::size_t ruleCount() const override { return " + str(static_cast<long long>(n)) + "; }\n";
        out += "    const RuleInfo& info(std::size_t rule) const override { return infos_[rule]; }\n\n";
        // Dispatch by switch: these run for every anchored search and every rewrite.
        auto perRule = [&](const std::string& inner, const std::function<std::string(std::size_t)>& body) {
            std::string t = inner + "switch (rule) {\n";
            for (std::size_t r = 0; r < n; ++r) t += inner + "case " + str(static_cast<long long>(r)) + ":\n" + body(r) + inner + "    break;\n";
            return t + inner + "default: break;\n" + inner + "}\n";
        };
        auto perDaughter = [&](const std::string& inner, const std::string& call) {
            return perRule(inner, [&](std::size_t r) {
                std::string t = inner + "    switch (daughter) {\n";
                for (std::size_t d = 0; d < prog_.rules[r].daughters.size(); ++d) {
                    const std::string rd = str(static_cast<long long>(r)) + "_" + str(static_cast<long long>(d));
                    t += inner + "    case " + str(static_cast<long long>(d)) + ": " + call.substr(0, call.find('@')) + rd +
                         call.substr(call.find('@') + 1) + "; break;\n";
                }
                return t + inner + "    default: break;\n" + inner + "    }\n";
            });
        };
        const std::string catchOp = "        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n";
        out += "    void findMatches(std::size_t rule, const Graph& g, MatchBuffer& out) override {\n" + names;
        out += "        current_ = names[rule];\n        try {\n";
        out += perRule("            ", [&](std::size_t r) { return "                match_" + str(static_cast<long long>(r)) + "(g, out);\n"; });
        out += catchOp + "    }\n\n";
        out += "    void findAnchored(std::size_t rule, const Graph& g, int node, NodeId host, MatchBuffer& out, EdgeId newFrom) override {\n" + names;
        out += "        current_ = names[rule];\n        try {\n";
        out += perRule("            ", [&](std::size_t r) {
            std::string t = "                switch (node) {\n";
            for (std::size_t a = 0; a < prog_.rules[r].nodes.size(); ++a)
                t += "                case " + str(static_cast<long long>(a)) + ": match_" + str(static_cast<long long>(r)) + "_a" +
                     str(static_cast<long long>(a)) + "(g, host, out, newFrom); break;\n";
            return t + "                default: break;\n                }\n";
        });
        out += "            (void)node; (void)host; (void)g; (void)out; (void)newFrom;\n" + catchOp + "    }\n\n";
        out += "    void repair(std::size_t rule, const Graph& g, const RepairArea& area, const RepairAnchor*, MatchSet& set, MatchBuffer&) override {\n" + names;
        out += "        current_ = names[rule];\n        try {\n";
        out += perRule("            ", [&](std::size_t r) { return "                repair_" + str(static_cast<long long>(r)) + "(g, area, set);\n"; });
        out += "            (void)g; (void)area; (void)set;\n" + catchOp + "    }\n\n";
        out += "    void writeSet(std::size_t rule, std::size_t daughter, Match m, WriteSet& w) const override {\n";
        out += perDaughter("        ", "writes_@(m, w)");
        out += "        (void)daughter; (void)m; (void)w;\n    }\n\n";
        out += emitWeigh();
        out += "    void prepare(std::size_t rule, std::size_t daughter, Match m, const Graph& g, Rng& rng, long long) override {\n" + names;
        out += "        rng_ = &rng;\n        current_ = names[rule];\n        try {\n";
        out += perDaughter("            ", "prepare_@(m, g)");
        out += "            (void)daughter; (void)m; (void)g;\n" + catchOp + "    }\n\n";
        // Prepared rewrites are applied in the order they were prepared.
        out += "    void commit(Graph& G, long long step) override {\n        for (const PendingRef& ref : pendingOrder_) {\n";
        out += "            switch (ref.daughter) {\n";
        std::string clears;
        int key = 0;
        for (std::size_t r = 0; r < n; ++r)
            for (std::size_t d = 0; d < prog_.rules[r].daughters.size(); ++d, ++key) {
                const std::string rd = str(static_cast<long long>(r)) + "_" + str(static_cast<long long>(d));
                out += "            case " + str(static_cast<long long>(key)) + ": apply_" + rd + "(G, step, pending_" + rd + "_[ref.index]); break;\n";
                clears += "        pending_" + rd + "_.clear();\n";
                const std::size_t loops = lower::lowerRewrite(prog_, prog_.rules[r], d).loops.size();
                for (std::size_t l = 0; l < loops; ++l)
                    clears += "        turns_" + rd + "_" + str(static_cast<long long>(l)) + "_.clear();\n";
            }
        out += "            default: break;\n            }\n            applicationDone(G);\n        }\n        (void)G; (void)step;\n        clearPending();\n    }\n\n";
        out += "    void discard() override { clearPending(); }\n\n";
        out += angleLayoutOverride(prog_);
        out += emitDrawingCost();
        out += "    void clearPending() {\n        pendingOrder_.clear();\n" + clears + "    }\n\n";
        out += emitPrefetchData(perRule);
        return out;
    }

    // The attribute records of a likely later pick's elements (the pick
    // lookahead asks once their graph records, which hold their slots, are
    // cached): a rewrite reads or writes them first thing.
    template <class PerRule>
    std::string emitPrefetchData(const PerRule& perRule) {
        std::string out = "    void prefetchData(std::size_t rule, Match m, const Graph& g) const override {\n";
        out += perRule("        ", [&](std::size_t r) {
            std::string t;
            const auto& rule = prog_.rules[r];
            auto ask = [&](int kind, const char* slot, const char* ids, std::size_t i) {
                if (kind < 0 || prog_.kinds[static_cast<std::size_t>(kind)].attrs.empty()) return;
                t += "            store_" + str(static_cast<long long>(kind)) + ".prefetch(g." + slot + "(m." + ids + "[" +
                     str(static_cast<long long>(i)) + "]));\n";
            };
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) ask(rule.nodes[i].kind, "nodeSlot", "nodes", i);
            for (std::size_t i = 0; i < rule.edges.size(); ++i) ask(rule.edges[i].kind, "edgeSlot", "edges", i);
            return t;
        });
        return out + "        (void)m; (void)g;\n    }\n\n";
    }

    // The command list, and faces that merging splits off (node_merge.hpp)
    // taking the attributes of the face they came from.
    std::string emitSequenceAndCopies() {
        std::string out;
        auto entries = [](const std::vector<rt::SequenceEntry>& list) {
            std::string e;
            for (const auto& x : list) e += std::string(e.empty() ? "" : ", ") + "{" + (x.compound ? "true" : "false") + ", " + str(static_cast<long long>(x.index)) + "}";
            return "{" + e + "}";
        };
        if (!prog_.sequence.empty()) {
            out += "    const std::vector<SequenceEntry>& sequence() const override {\n        static const std::vector<SequenceEntry> list = " +
                   entries(lower::sequenceOf(prog_)) + ";\n        return list;\n    }\n\n";
        }
        if (!prog_.compounds.empty()) {
            std::string list;
            for (const auto& c : lower::compoundsOf(prog_))
                list += "            {" + cppString(c.name) + ", " + str(static_cast<long long>(c.matchRule)) + ", " + entries(c.entries) + "},\n";
            out += "    const std::vector<CompoundInfo>& compounds() const override {\n        static const std::vector<CompoundInfo> list = {\n" + list +
                   "        };\n        return list;\n    }\n\n";
            out += emitCompoundValues();
        }
        std::string cases;
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            if (prog_.kinds[k].cls != ir::ElemClass::Face || prog_.kinds[k].attrs.empty()) continue;
            const std::string sk = str(static_cast<long long>(k));
            cases += "        case " + sk + ": G.setFaceSlot(to, store_" + sk + ".add(store_" + sk + "[G.faceSlot(from)])); break;\n";
        }
        out += addFaceWithDefaults();
        if (cases.empty()) return out;   // no face has attributes: nothing to copy
        out += "    void copyFaceAttributes(Graph& G, FaceId from, FaceId to) override {\n        switch (G.faceKind(from)) {\n" + cases +
               "        default: break;\n        }\n    }\n\n";
        return out;
    }

    // Faces the run adds itself (`layout angles`), with their kinds' default records.
    std::string addFaceWithDefaults() {
        std::string cases;
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            if (prog_.kinds[k].cls != ir::ElemClass::Face || prog_.kinds[k].attrs.empty()) continue;
            const std::string sk = str(static_cast<long long>(k));
            cases += "        case " + sk + ": G.setFaceSlot(f, store_" + sk + ".add(default_" + sk + ")); break;\n";
        }
        if (cases.empty() || !prog_.angleLayout) return "";
        return "    FaceId addFaceWithDefaults(Graph& G, int kind, std::span<const NodeId> corners, long long age) override {\n"
               "        const FaceId f = G.addFace(kind, corners, age);\n        switch (kind) {\n" + cases +
               "        default: break;\n        }\n        return f;\n    }\n\n";
    }

    // Each compound's lets, on the match of its match rule (RuleSet::compoundValues).
    std::string emitCompoundValues() {
        std::string out = "    std::vector<Value> compoundValues(std::size_t compound, Match m, const Graph& g, Rng& rng) override {\n";
        out += "        rng_ = &rng;\n        switch (compound) {\n";
        for (std::size_t c = 0; c < prog_.compounds.size(); ++c) {
            const ir::Rule& r = prog_.rules[static_cast<std::size_t>(prog_.compounds[c].matchRule)];
            if (r.lets.empty()) continue;
            const ExprContext ctx = matchElements(r);
            const std::string in = "                ";
            std::string body, values;
            for (const auto& l : r.lets) {
                const std::string v = gen_.gen(l.value, ctx, body, in);
                const std::string name = "L" + str(l.slot);
                body += in + "const " + cppType(l.value.type) + " " + name + " = " + v + ";\n";
                values += (values.empty() ? "" : ", ") + valueOf(l.value.type, name);
            }
            out += "        case " + str(static_cast<long long>(c)) + ":\n            current_ = " + cLiteral(r.name) + ";\n            try {\n" + body +
                   in + "return {" + values + "};\n            } catch (const OpError& e) {\n                throw PlacedError(loc_, e.what());\n            }\n";
        }
        return out + "        default: break;\n        }\n        (void)m;\n        (void)g;\n        return {};\n    }\n\n";
    }

    std::string emitAttribute() {
        std::string out = "    Value attribute(ElemClass cls, std::uint32_t id, int attr) const override {\n";
        out += "        const int kind = graph_.kindOf(cls, id);\n";
        out += "        const std::uint32_t slot = graph_.slotOf(cls, id);\n        (void)slot; (void)attr;\n";
        out += "        switch (kind) {\n";
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            const auto& kind = prog_.kinds[k];
            if (kind.attrs.empty()) continue;
            out += "        case " + str(static_cast<long long>(k)) + ": {\n            const auto& r = store_" + str(static_cast<long long>(k)) + "[slot];\n            switch (attr) {\n";
            for (std::size_t a = 0; a < kind.attrs.size(); ++a)
                out += "            case " + str(static_cast<long long>(a)) + ": return " + valueOf(kind.attrs[a].type, "r.a" + str(static_cast<long long>(a))) + ";\n";
            out += "            default: break;\n            }\n            break;\n        }\n";
        }
        out += "        default: break;\n        }\n        return Value{0LL};\n    }\n\n";
        return out;
    }

    // Each kind's style properties (style_K); what is drawn, and how an
    // element's own assignments join them, is rt::drawItems'.
    std::string emitStyles() {
        std::string out;
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            const auto& kind = prog_.kinds[k];
            out += "    void style_" + str(static_cast<long long>(k)) + "(DrawItem& it) {\n        (void)it;\n";
            ExprContext ctx;
            ctx.self = "it.id";
            ctx.selfClass = kind.cls;
            ctx.selfKind = static_cast<int>(k);
            ctx.graph = "graph_";
            for (const auto& p : kind.style) {
                const std::string v = gen_.gen(p.value, ctx, out, "        ");
                // The name is an identifier; the item keeps a view of the literal.
                out += "        it.props.push_back(StyleOverride{std::string_view(\"" + p.name + "\"), " + valueOf(p.value.type, v) + "});\n";
            }
            out += "    }\n\n";
        }
        out += "    void drawItem(ElemClass cls, std::uint32_t id, DrawItem& out) override {\n        try {\n"
               "            rt::drawItem(graph_, cls, id, schema_.enumValueNames, [this](DrawItem& it, int kind) {\n"
               "                switch (kind) {\n";
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k)
            out += "                case " + str(static_cast<long long>(k)) + ": style_" + str(static_cast<long long>(k)) + "(it); break;\n";
        out += "                default: break;\n                }\n            }, out);\n";
        out += "        } catch (const OpError& e) {\n            throw PlacedError(loc_, e.what());\n        }\n    }\n\n";
        return out;
    }

    std::string emitMembers() {
        std::string out = "    Params P_;\n    Consts C_;\n    Rng* rng_ = nullptr;\n    int loc_ = -1;\n    const char* current_ = \"\";  // the rule being matched or applied (no copy in the hot path)\n";
        out += "    Graph graph_;\n    std::vector<ParamSpec> specs_;\n    JsonSchema schema_;\n    std::vector<std::string> defs_;\n";
        out += "    std::vector<RuleInfo> infos_;\n" + constants_.definitions();
        out += "    struct PendingRef {\n        std::uint32_t daughter, index;\n    };\n    GrowArray<PendingRef> pendingOrder_;\n";
        out += "    std::vector<NodeId> loopNodes_;   // a `for` loop's new nodes, turn by turn\n";
        out += "    std::vector<NodeId> splitChosen_;   // a split's chosen corners\n";
        for (std::size_t k = 0; k < prog_.kinds.size(); ++k) {
            if (prog_.kinds[k].attrs.empty()) continue;
            const std::string sk = str(static_cast<long long>(k));
            out += "    Store<Kind" + sk + "> store_" + sk + ";\n    Kind" + sk + " default_" + sk + ";\n";
        }
        return out;
    }

    const ir::Program& prog_;
    const EmitOptions& options_;
    Places places_;
    ConstantValues constants_;
    ExprGen gen_;
};

}  // namespace

std::string emitCpp(const ir::Program& prog, const EmitOptions& options) { return ProgramEmitter(prog, options).emit(); }

}  // namespace g2d::emit
