#include "lower/kind_effects.hpp"

#include "lower/fact_reads.hpp"

#include <algorithm>
#include <set>

namespace g2d::lower {

namespace {

class KindSet {
public:
    explicit KindSet(const std::vector<ir::Kind>& kinds) : kinds_(kinds) {}
    // A kind, or every kind of the class for -1 (a wildcard, or after an error).
    void add(int kind, ir::ElemClass cls) {
        if (kind >= 0) {
            set_.insert(kind);
            return;
        }
        for (std::size_t k = 0; k < kinds_.size(); ++k)
            if (kinds_[k].cls == cls) set_.insert(static_cast<int>(k));
    }
    std::vector<int> sorted() const { return {set_.begin(), set_.end()}; }

private:
    const std::vector<ir::Kind>& kinds_;
    std::set<int> set_;
};

template <class T>
const T* at(const std::vector<T>& v, int i) {
    return i >= 0 && static_cast<std::size_t>(i) < v.size() ? &v[static_cast<std::size_t>(i)] : nullptr;
}

// The node attributes `e` reads; `kindOf` gives a node's kind by its index
// in the rule's numbering (match nodes, then a negative condition's).
template <class KindOf>
void readValues(const ir::Expr& e, const KindOf& kindOf, const ir::Rule& rule, const ir::NegativeCondition* nac,
                std::set<long long>& out) {
    if (e.op == ir::ExprOp::Attr && e.elem.cls == ir::ElemClass::Node) {
        const int kind = kindOf(e.elem.index);
        if (kind >= 0) out.insert(valueKey(kind, e.index));
    }
    if (e.op == ir::ExprOp::Attr && e.elem.cls == ir::ElemClass::Face) {
        const int i = e.elem.index, outer = static_cast<int>(rule.faces.size());
        const ir::PatternFace* f = i < outer ? at(rule.faces, i) : nac ? at(nac->faces, i - nac->outerFaces) : nullptr;
        if (f && f->kind >= 0) out.insert(valueKey(f->kind, e.index));
    }
    for (const auto& a : e.args) readValues(a, kindOf, rule, nac, out);
}

// The kinds and attributes daughter `d` changes (KindEffects).
void describeDaughter(const ir::Rule& rule, const ir::Daughter& d, const std::vector<ir::Kind>& kinds, KindEffects& out) {
    KindSet changed(kinds);
    std::set<long long> values;
    for (int n : d.deletedNodes)
        changed.add(at(rule.nodes, n) ? at(rule.nodes, n)->kind : -1, ir::ElemClass::Node);
    for (int e : d.deletedEdges)
        changed.add(at(rule.edges, e) ? at(rule.edges, e)->kind : -1, ir::ElemClass::Edge);
    for (const auto& n : d.nodes) {
        const ir::PatternNode* mother = at(rule.nodes, n.motherNode);
        if (!mother) {
            changed.add(n.kind, ir::ElemClass::Node);   // new
            continue;
        }
        const bool retyped = n.kind != mother->kind;
        if (retyped) changed.add(n.kind, ir::ElemClass::Node);
        if (retyped || n.position || n.radius) changed.add(mother->kind, ir::ElemClass::Node);
        for (const auto& a : n.assigns) values.insert(valueKey(n.kind, a.attr));
    }
    out.changedValues.emplace_back(values.begin(), values.end());
    for (const auto& e : d.edges) {
        const ir::PatternEdge* mother = at(rule.edges, e.motherEdge);
        if (!mother) {
            changed.add(e.kind, ir::ElemClass::Edge);   // new
            continue;
        }
        const bool retyped = e.kind != mother->kind;
        if (retyped) changed.add(e.kind, ir::ElemClass::Edge);
        if (retyped || ir::keptEdgeRewired(rule, d, e) || !e.assigns.empty()) changed.add(mother->kind, ir::ElemClass::Edge);
    }
    for (const auto& f : d.faces) changed.add(f.kind, ir::ElemClass::Face);   // new
    for (const auto& ins : d.inserts) {   // faces of any kind grow a corner
        changed.add(-1, ir::ElemClass::Face);
        for (int n : {ins.node, ins.first, ins.second})
            if (const ir::DaughterNode* dn = at(d.nodes, n)) changed.add(dn->kind, ir::ElemClass::Node);
    }
    for (const auto& sp : d.splits) {   // new, and the corners' edges
        if (sp.centre) changed.add(sp.centre->kind, ir::ElemClass::Node);
        changed.add(sp.edgeKind, ir::ElemClass::Edge);
        changed.add(at(rule.faces, sp.motherFace) ? at(rule.faces, sp.motherFace)->kind : -1, ir::ElemClass::Face);
        changed.add(-1, ir::ElemClass::Node);   // corners of any kind gain an edge
    }
    for (const auto& l : d.loops) {   // new, every turn
        for (const auto& n : l.nodes) changed.add(n.kind, ir::ElemClass::Node);
        for (const auto& e : l.edges) changed.add(e.kind, ir::ElemClass::Edge);
        for (const auto& f : l.faces) changed.add(f.kind, ir::ElemClass::Face);
    }
    for (int f : d.deletedFaces) changed.add(at(rule.faces, f) ? at(rule.faces, f)->kind : -1, ir::ElemClass::Face);
    for (const auto& k : d.keptFaces)
        if (const auto* f = at(rule.faces, k.motherFace); f && f->kind >= 0)
            for (const auto& a : k.assigns) values.insert(valueKey(f->kind, a.attr));
    out.changedValues.back().assign(values.begin(), values.end());
    out.changedKinds.push_back(changed.sorted());
}

}  // namespace

KindEffects kindEffects(const ir::Rule& rule, const std::vector<ir::Kind>& kinds) {
    KindEffects out;
    KindSet read(kinds);
    for (const auto& n : rule.nodes) read.add(n.kind, ir::ElemClass::Node);
    for (const auto& e : rule.edges) read.add(e.kind, ir::ElemClass::Edge);
    for (const auto& f : rule.faces) read.add(f.kind, ir::ElemClass::Face);
    std::uint8_t reads = factReads(rule.conditions);
    std::set<long long> values;
    const auto matchKind = [&](int i) { return at(rule.nodes, i) ? at(rule.nodes, i)->kind : -1; };
    for (const auto& c : rule.conditions) readValues(c.expr, matchKind, rule, nullptr, values);
    for (const auto& nac : rule.nacs) {
        for (const auto& n : nac.nodes) read.add(n.kind, ir::ElemClass::Node);
        for (const auto& e : nac.edges) read.add(e.kind, ir::ElemClass::Edge);
        for (const auto& f : nac.faces) read.add(f.kind, ir::ElemClass::Face);
        reads |= factReads(nac.conditions);
        const auto nacKind = [&](int i) {
            return i < nac.outerNodes ? matchKind(i) : at(nac.nodes, i - nac.outerNodes) ? at(nac.nodes, i - nac.outerNodes)->kind : -1;
        };
        for (const auto& c : nac.conditions) readValues(c.expr, nacKind, rule, &nac, values);
    }
    // A face's geometry moves with any corner, of any node kind, and
    // removing a node removes its faces; face counts count every face kind.
    bool facePatterns = !rule.faces.empty();
    for (const auto& nac : rule.nacs) facePatterns = facePatterns || !nac.faces.empty();
    const bool facesCounted = reads & (rt::kReadsFacesAt | rt::kReadsFaceSides);
    out.readsDegrees = (reads & rt::kReadsEdgesAt) || facePatterns || facesCounted;
    if (facePatterns || facesCounted) read.add(-1, ir::ElemClass::Node);
    if (facesCounted) read.add(-1, ir::ElemClass::Face);
    out.readsNeighbours = reads & rt::kReadsFaceSides;
    out.readValues.assign(values.begin(), values.end());
    // A degree counts the edges of every kind.
    if (out.readsDegrees) read.add(-1, ir::ElemClass::Edge);
    out.readKinds = read.sorted();
    for (const auto& d : rule.daughters) describeDaughter(rule, d, kinds, out);
    return out;
}

}  // namespace g2d::lower
