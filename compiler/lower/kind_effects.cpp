#include "lower/kind_effects.hpp"

#include "lower/fact_reads.hpp"
#include "lower/kind_set.hpp"

#include <algorithm>
#include <set>

namespace g2d::lower {

namespace {

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
    return out;
}

}  // namespace g2d::lower
