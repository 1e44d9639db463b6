#include "parse/ast_builder.hpp"
#include "g2d/utf8.hpp"

#include <stdexcept>

#include <cstdlib>

namespace g2d {

namespace {

using namespace ast;
using P = G2dParser;

std::uint32_t codePoints(const std::string& s) { return static_cast<std::uint32_t>(rt::codePointCount(s)); }

// Unescapes a string literal's body (without the quotes).
std::string unescape(const std::string& quoted) {
    std::string out;
    for (std::size_t i = 1; i + 1 < quoted.size(); ++i) {
        char c = quoted[i];
        if (c != '\\' || i + 2 >= quoted.size()) { out += c; continue; }
        char e = quoted[++i];
        switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case '0': out += '\0'; break;
        default: out += e; break;  // \" \\ and anything else stand for themselves
        }
    }
    return out;
}

class Builder {
public:
    explicit Builder(FileId file) : file_(file) {}

    Span span(antlr4::Token* start, antlr4::Token* stop) const {
        Span s;
        s.file = file_;
        s.line = static_cast<std::uint32_t>(start->getLine());
        s.col = static_cast<std::uint32_t>(start->getCharPositionInLine() + 1);
        if (!stop || stop->getType() == antlr4::Token::EOF) stop = start;
        s.endLine = static_cast<std::uint32_t>(stop->getLine());
        s.endCol = static_cast<std::uint32_t>(stop->getCharPositionInLine() + 1) + codePoints(stop->getText());
        return s;
    }
    Span span(antlr4::ParserRuleContext* ctx) const { return span(ctx->getStart(), ctx->getStop()); }
    Span span(antlr4::Token* t) const { return span(t, t); }
    Span span(antlr4::tree::TerminalNode* n) const { return span(n->getSymbol()); }

    Ident ident(antlr4::tree::TerminalNode* n) const { return Ident{n->getText(), span(n)}; }
    Ident ident(antlr4::Token* t) const { return Ident{t->getText(), span(t)}; }
    // `name`, or `prev.name` / `next.name` (sema tells where those may stand).
    Ident nodeRef(P::NodeRefContext* ctx) const { return Ident{ctx->getText(), span(ctx)}; }

    ProduceStmt produceStmt(P::ProduceStmtContext* s) {
        if (s->letStmt()) return ProduceStmt{let(s->letStmt())};
        if (s->graphStmt()) return ProduceStmt{graphStmt(s->graphStmt())};
        if (auto* i = s->insertStmt()) return ProduceStmt{InsertStmt{ident(i->node), ident(i->first), ident(i->second), span(i)}};
        if (auto* sp = s->splitStmt()) return ProduceStmt{split(sp)};
        auto* f = s->forStmt();
        ForBlock b;
        b.span = span(f);
        if (f->var) b.vars.push_back(ident(f->var));
        else b.vars = {ident(f->first), ident(f->second)};
        b.face = ident(f->face);
        b.what = ident(f->what);
        for (auto* inner : f->produceStmt()) b.body.push_back(produceStmt(inner));
        return ProduceStmt{std::move(b)};
    }
    SplitStmt split(P::SplitStmtContext* ctx) {
        SplitStmt s;
        s.span = span(ctx);
        s.face = ident(ctx->face);
        if (ctx->centreKind) {
            SplitStmt::Centre c;
            c.kind = ident(ctx->centreKind);
            c.position = expr(ctx->position()->expr());
            if (ctx->centre) c.assigns = assignments(ctx->centre);
            c.span = span(ctx->centreKind, ctx->centre ? ctx->centre->getStop() : ctx->position()->getStop());
            s.centre = std::move(c);
        }
        s.edgeKind = ident(ctx->edgeKind);
        if (ctx->edge) s.edgeAssigns = assignments(ctx->edge);
        if (ctx->var) {
            s.var = ident(ctx->var);
            s.loopFace = ident(ctx->loopFace);
            s.what = ident(ctx->what);
            s.cond = expr(ctx->expr());
        }
        return s;
    }
    TypeRef typeRef(P::TypeRefContext* ctx) const { return TypeRef{ident(ctx->ID())}; }

    Program program(P::ProgramContext* ctx) {
        Program p;
        p.file = file_;
        for (auto* d : ctx->topDecl()) p.decls.push_back(decl(d));
        return p;
    }

    Decl decl(P::TopDeclContext* ctx) {
        if (auto* c = ctx->importDecl())
            return Decl{ImportDecl{unescape(c->STRING()->getText()), span(c)}};
        if (auto* c = ctx->paramDecl()) {
            ParamDecl d{ident(c->name), typeRef(c->typeRef()), expr(c->expr()), span(c), std::nullopt};
            if (auto* r = c->paramRange()) {
                ParamRange range{expr(r->lower), expr(r->upper), std::nullopt, nullptr, span(r)};
                if (r->stepWord) {
                    range.stepWord = ident(r->stepWord);
                    range.step = expr(r->step);
                }
                d.range = std::move(range);
            }
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->constDecl()) {
            ConstDecl d{ident(c->ID()), std::nullopt, expr(c->expr()), span(c)};
            if (c->typeRef()) d.type = typeRef(c->typeRef());
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->enumDecl()) {
            EnumDecl d{ident(c->ID(0)), {}, span(c)};
            for (std::size_t i = 1; i < c->ID().size(); ++i) d.values.push_back(ident(c->ID(i)));
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->fnDecl()) {
            FnDecl d{ident(c->ID()), {}, typeRef(c->typeRef()), expr(c->expr()), span(c)};
            for (auto* p : c->fnParam()) d.params.push_back(FnParam{ident(p->ID()), typeRef(p->typeRef())});
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->kindDecl()) return Decl{kind(c)};
        if (auto* c = ctx->axiomDecl()) {
            AxiomDecl d{{}, span(c)};
            for (auto* g : c->graphStmt()) d.body.push_back(graphStmt(g));
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->limitDecl()) return Decl{LimitDecl{expr(c->expr()), span(c)}};
        if (auto* c = ctx->spaceDecl()) return Decl{SpaceDecl{c->SPACE_DIM()->getText()[0] == '3' ? 3 : 2, span(c)}};
        if (auto* c = ctx->priorityDecl()) {
            PriorityDecl d;
            d.priority = signedInt(c->signedInt(), d.priorityOverflow);
            d.prioritySpan = span(c->signedInt());
            d.span = span(c);
            for (auto* o : c->priorityOption()) {
                if (auto* l = dynamic_cast<P::PriorityLimitContext*>(o)) {
                    if (d.limit) d.repeatedOptions.push_back(span(o));
                    d.limit = expr(l->expr());
                } else if (dynamic_cast<P::PriorityParallelContext*>(o)) {
                    if (d.parallel) d.repeatedOptions.push_back(span(o));
                    d.parallel = true;
                } else if (auto* w = dynamic_cast<P::PriorityWordContext*>(o)) {
                    if (w->ID()->getText() != "generation") {
                        d.unknownOptions.push_back(ident(w->ID()));
                        continue;
                    }
                    if (d.generation) d.repeatedOptions.push_back(span(o));
                    d.generation = true;
                } else {
                    throw std::logic_error("a priority option of the grammar the AST builder does not know: " + o->getText());
                }
            }
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->defsDecl()) return Decl{DefsDecl{unescape(c->STRING()->getText()), span(c)}};
        if (auto* c = ctx->mergeDecl()) return Decl{MergeDecl{expr(c->expr()), span(c)}};
        if (auto* c = ctx->sequenceDecl()) return Decl{sequence(c)};
        if (auto* c = ctx->layoutDecl()) {
            LayoutDecl d{ident(c->ID()), {}, span(c)};
            for (auto* p : c->styleProp()) d.props.push_back(StyleProp{ident(p->ID()), expr(p->expr()), span(p)});
            return Decl{std::move(d)};
        }
        if (auto* c = ctx->canvasDecl()) return Decl{CanvasDecl{expr(c->lower), ident(c->to), expr(c->upper), span(c)}};
        if (auto* c = ctx->compoundDecl()) {
            CompoundDecl d;
            d.span = span(c);
            d.match.name = ident(c->ID());
            d.match.span = span(c);
            d.match.matchSpan = span(c->matchBlock());
            for (auto* m : c->matchBlock()->matchStmt()) d.match.match.push_back(matchStmt(m));
            for (auto* l : c->letStmt()) d.match.items.push_back(RuleItem{let(l)});
            d.match.compoundMatch = true;
            ProduceBlock none;
            none.span = d.match.matchSpan;
            d.match.items.push_back(RuleItem{std::move(none)});
            d.body = SequenceDecl{std::nullopt, sequenceItems(c->sequenceBody()), span(c->sequenceBody())};
            return Decl{std::move(d)};
        }
        return Decl{rule(ctx->ruleDecl())};
    }

    SequenceDecl sequence(P::SequenceDeclContext* c) {
        SequenceDecl d{std::nullopt, sequenceItems(c->sequenceBody()), span(c)};
        if (c->name) d.name = ident(c->name);
        return d;
    }

    std::vector<SequenceItem> sequenceItems(P::SequenceBodyContext* c) {
        std::vector<SequenceItem> out;
        for (auto* item : c->sequenceItem()) {
            SequenceItem it;
            it.span = span(item);
            if (auto* n = dynamic_cast<P::SequenceNameContext*>(item)) {
                it.name = ident(n->ID());
            } else if (auto* r = dynamic_cast<P::SequenceRepeatContext*>(item)) {
                it.count = expr(r->expr());
                it.body = sequenceItems(r->sequenceBody());
            } else {
                throw std::logic_error("a sequence entry of the grammar the AST builder does not know: " + item->getText());
            }
            out.push_back(std::move(it));
        }
        return out;
    }

    // Priorities are written as integers; `overflow` flags values beyond 64 bits.
    long long signedInt(P::SignedIntContext* c, bool& overflow) {
        const bool negative = c->children.size() > 1;
        const std::string text = (negative ? "-" : "") + c->INT()->getText();
        errno = 0;
        long long v = std::strtoll(text.c_str(), nullptr, 10);
        overflow = errno == ERANGE;
        return v;
    }

    double signedNumber(P::SignedNumberContext* c) {
        auto* num = c->INT() ? c->INT() : c->FLOAT();
        double v = std::strtod(num->getText().c_str(), nullptr);
        return c->children.size() > 1 ? -v : v;
    }

    KindDecl kind(P::KindDeclContext* ctx) {
        KindDecl k;
        k.span = span(ctx);
        P::KindBodyContext* body = nullptr;
        if (auto* n = dynamic_cast<P::NodeKindContext*>(ctx)) {
            k.name = ident(n->ID());
            body = n->kindBody();
        } else if (auto* f = dynamic_cast<P::FaceKindContext*>(ctx)) {
            k.cls = KindDecl::Class::Face;
            k.name = ident(f->ID(0));
            if (f->option) k.option = ident(f->option);
            body = f->kindBody();
        } else {
            auto* e = static_cast<P::EdgeKindContext*>(ctx);
            k.cls = KindDecl::Class::Edge;
            k.name = ident(e->ID());
            if (e->DIRECTED) k.directed = true;
            if (e->UNDIRECTED) k.directed = false;
            body = e->kindBody();
        }
        for (auto* m : body->kindMember()) {
            if (auto* a = dynamic_cast<P::AttrDeclContext*>(m)) {
                AttrDecl d{ident(a->ID()), typeRef(a->typeRef()), nullptr, span(a)};
                if (a->expr()) d.value = expr(a->expr());
                k.attrs.push_back(std::move(d));
            } else if (auto* l = dynamic_cast<P::LayoutBlockContext*>(m)) {
                k.hasLayout = true;
                for (auto* p : l->styleProp())
                    k.layout.push_back(StyleProp{ident(p->ID()), expr(p->expr()), span(p)});
            } else {
                auto* s = static_cast<P::StyleBlockContext*>(m);
                for (auto* p : s->styleProp())
                    k.style.push_back(StyleProp{ident(p->ID()), expr(p->expr()), span(p)});
            }
        }
        return k;
    }

    std::vector<Assignment> assignments(P::AssignmentsContext* ctx) {
        std::vector<Assignment> out;
        if (!ctx) return out;
        for (auto* a : ctx->assignment())
            out.push_back(Assignment{a->isStyle != nullptr, ident(a->ID()), expr(a->expr())});
        return out;
    }

    GraphStmt graphStmt(P::GraphStmtContext* ctx) {
        if (auto* n = ctx->nodeStmt()) {
            NodeStmt s;
            s.span = span(n);
            s.name = ident(n->ID(0));
            if (n->kind) { s.kind = ident(n->kind); s.kindSpan = span(n->kind); }
            if (n->wild) { s.wildcard = true; s.kindSpan = span(n->wild); }
            if (auto* sk = n->sketch())
                s.sketch = Sketch{signedNumber(sk->signedNumber(0)), signedNumber(sk->signedNumber(1)), span(sk)};
            if (auto* p = n->position()) s.position = expr(p->expr());
            if (n->assignments()) { s.hasAssignBlock = true; s.assigns = assignments(n->assignments()); }
            if (auto* w = n->whereClause()) s.where = expr(w->expr());
            return GraphStmt{std::move(s)};
        }
        if (auto* f = ctx->faceStmt()) {
            FaceStmt s;
            s.span = span(f);
            if (f->name) s.name = ident(f->name);
            s.kind = ident(f->kind);
            for (auto* c : f->corners) s.corners.push_back(nodeRef(c));
            if (auto* r = f->ring) {
                s.ring = RingCorners{ident(r->every), ident(r->node), std::nullopt, span(r)};
                if (r->order) s.ring->order = ident(r->order);
            }
            s.assigns = assignments(f->assignments());
            if (auto* w = f->whereClause()) s.where = expr(w->expr());
            return GraphStmt{std::move(s)};
        }
        auto* e = ctx->edgeStmt();
        EdgeStmt s;
        s.span = span(e);
        if (e->name) s.name = ident(e->name);
        s.src = nodeRef(e->src);
        s.dst = nodeRef(e->dst);
        P::EdgeLabelContext* label = nullptr;
        if (auto* a = dynamic_cast<P::DirectedArrowContext*>(e->edgeArrow())) {
            s.arrow = EdgeStmt::Arrow::Forward; label = a->edgeLabel();
        } else if (auto* b = dynamic_cast<P::ReversedArrowContext*>(e->edgeArrow())) {
            s.arrow = EdgeStmt::Arrow::Backward; label = b->edgeLabel();
        } else {
            s.arrow = EdgeStmt::Arrow::Undirected;
            label = static_cast<P::UndirectedArrowContext*>(e->edgeArrow())->edgeLabel();
        }
        s.kind = ident(label->ID());
        s.assigns = assignments(label->assignments());
        if (auto* w = e->whereClause()) s.where = expr(w->expr());
        return GraphStmt{std::move(s)};
    }

    MatchStmt matchStmt(P::MatchStmtContext* ctx) {
        if (auto* g = dynamic_cast<P::MatchGraphContext*>(ctx)) return MatchStmt{graphStmt(g->graphStmt())};
        if (auto* w = dynamic_cast<P::MatchWhereContext*>(ctx))
            return MatchStmt{WhereStmt{expr(w->expr()), span(w)}};
        auto* n = static_cast<P::MatchNacContext*>(ctx);
        NacBlock nac{{}, span(n)};
        for (auto* m : n->matchStmt()) nac.body.push_back(matchStmt(m));
        return MatchStmt{std::move(nac)};
    }

    LetStmt let(P::LetStmtContext* ctx) {
        LetStmt l{ident(ctx->ID()), std::nullopt, expr(ctx->expr()), span(ctx)};
        if (ctx->typeRef()) l.type = typeRef(ctx->typeRef());
        return l;
    }

    RuleDecl rule(P::RuleDeclContext* ctx) {
        RuleDecl r;
        r.span = span(ctx);
        r.name = ident(ctx->ID());
        for (auto* o : ctx->ruleOption()) {
            RuleOption opt;
            opt.span = span(o);
            if (auto* p = dynamic_cast<P::RulePriorityContext*>(o)) {
                opt.kind = RuleOption::Kind::Priority;
                opt.priority = signedInt(p->signedInt(), opt.priorityOverflow);
            } else if (auto* k = dynamic_cast<P::RulePickContext*>(o)) {
                opt.kind = RuleOption::Kind::Pick;
                opt.pick = ident(k->how);
                if (k->measure) opt.pickMeasure = ident(k->measure);
            } else if (dynamic_cast<P::RuleOrderedContext*>(o)) {
                opt.kind = RuleOption::Kind::Ordered;
            } else if (dynamic_cast<P::RuleParallelContext*>(o)) {
                opt.kind = RuleOption::Kind::Parallel;
            } else if (auto* w = dynamic_cast<P::RuleWordOptionContext*>(o)) {
                opt.kind = RuleOption::Kind::Word;
                opt.word = ident(w->word);
            } else if (auto* rw = dynamic_cast<P::RuleWeightContext*>(o)) {
                opt.kind = RuleOption::Kind::Weight;
                opt.weight = expr(rw->expr());
            } else if (auto* rl = dynamic_cast<P::RuleLimitContext*>(o)) {
                opt.kind = RuleOption::Kind::Limit;
                opt.limit = expr(rl->expr());
            } else {
                throw std::logic_error("a rule option of the grammar the AST builder does not know: " + o->getText());
            }
            r.options.push_back(std::move(opt));
        }
        r.matchSpan = span(ctx->matchBlock());
        for (auto* m : ctx->matchBlock()->matchStmt()) r.match.push_back(matchStmt(m));
        for (auto* item : ctx->ruleItem()) {
            if (auto* l = item->letStmt()) { r.items.push_back(RuleItem{let(l)}); continue; }
            auto* p = item->produceBlock();
            ProduceBlock b;
            b.span = span(p);
            if (p->expr()) b.weight = expr(p->expr());
            for (auto* s : p->produceStmt()) b.body.push_back(produceStmt(s));
            r.items.push_back(RuleItem{std::move(b)});
        }
        return r;
    }

    ExprPtr make(Span s, auto node) {
        auto e = std::make_unique<Expr>();
        e->span = s;
        e->node = std::move(node);
        return e;
    }

    static BinaryOp binaryOp(const std::string& op) {
        if (op == "+") return BinaryOp::Add;
        if (op == "-") return BinaryOp::Sub;
        if (op == "*") return BinaryOp::Mul;
        if (op == "/") return BinaryOp::Div;
        if (op == "%") return BinaryOp::Mod;
        if (op == "<") return BinaryOp::Lt;
        if (op == "<=") return BinaryOp::Le;
        if (op == ">") return BinaryOp::Gt;
        if (op == ">=") return BinaryOp::Ge;
        if (op == "==") return BinaryOp::Eq;
        if (op == "!=") return BinaryOp::Ne;
        if (op == "and" || op == "&&") return BinaryOp::And;
        return BinaryOp::Or;
    }

    ExprPtr binary(P::ExprContext* ctx, antlr4::Token* op, P::ExprContext* l, P::ExprContext* r) {
        return make(span(ctx), Binary{binaryOp(op->getText()), expr(l), expr(r), span(op)});
    }

    ExprPtr expr(P::ExprContext* ctx) {
        Span s = span(ctx);
        if (auto* c = dynamic_cast<P::PrimaryExprContext*>(ctx)) return primary(c->primary());
        if (auto* c = dynamic_cast<P::MemberExprContext*>(ctx))
            return make(s, Member{expr(c->expr()), ident(c->ID())});
        if (auto* c = dynamic_cast<P::UnaryExprContext*>(ctx)) {
            std::string op = c->op->getText();
            UnaryOp u = op == "-" ? UnaryOp::Neg : op == "+" ? UnaryOp::Plus : UnaryOp::Not;
            return make(s, Unary{u, expr(c->expr())});
        }
        if (auto* c = dynamic_cast<P::NotExprContext*>(ctx)) return make(s, Unary{UnaryOp::Not, expr(c->expr())});
        if (auto* c = dynamic_cast<P::MulExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        if (auto* c = dynamic_cast<P::AddExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        if (auto* c = dynamic_cast<P::RelExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        if (auto* c = dynamic_cast<P::EqExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        if (auto* c = dynamic_cast<P::AndExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        if (auto* c = dynamic_cast<P::OrExprContext*>(ctx)) return binary(c, c->op, c->expr(0), c->expr(1));
        auto* c = static_cast<P::CondExprContext*>(ctx);
        return make(s, Conditional{expr(c->expr(0)), expr(c->expr(1)), expr(c->expr(2))});
    }

    ExprPtr primary(P::PrimaryContext* ctx) {
        Span s = span(ctx);
        if (auto* c = dynamic_cast<P::IntLitContext*>(ctx)) {
            errno = 0;
            long long v = std::strtoll(c->INT()->getText().c_str(), nullptr, 10);
            // Out-of-range literals are reported by sema.
            return make(s, IntLit{v, errno == ERANGE});
        }
        if (auto* c = dynamic_cast<P::FloatLitContext*>(ctx))
            return make(s, FloatLit{std::strtod(c->FLOAT()->getText().c_str(), nullptr)});
        if (auto* c = dynamic_cast<P::StringLitContext*>(ctx)) return make(s, StringLit{unescape(c->STRING()->getText())});
        if (auto* c = dynamic_cast<P::BoolLitContext*>(ctx)) return make(s, BoolLit{c->getText() == "true"});
        if (auto* c = dynamic_cast<P::CallExprContext*>(ctx)) {
            Call call{ident(c->ID()), {}};
            for (auto* a : c->expr()) call.args.push_back(expr(a));
            return make(s, std::move(call));
        }
        if (auto* c = dynamic_cast<P::NameExprContext*>(ctx)) return make(s, Name{c->name->getText()});
        if (auto* c = dynamic_cast<P::VecLitContext*>(ctx))
            return make(s, VecLit{expr(c->expr(0)), expr(c->expr(1)), c->expr().size() > 2 ? expr(c->expr(2)) : nullptr});
        return expr(static_cast<P::ParenExprContext*>(ctx)->expr());
    }

private:
    FileId file_;
};

}  // namespace

ast::Program buildAst(G2dParser::ProgramContext* tree, FileId file) { return Builder(file).program(tree); }

}  // namespace g2d
