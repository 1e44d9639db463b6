#include "g2d/element_facts.hpp"

namespace g2d::rt {

namespace {

const ElementFactEntry kFacts[] = {
#define G2D_FACT_ENTRY(id, fn, name, type, typeName, classes, spaces, reads, meaning) \
    {ElemFact::id, #fn, #name, typeName, classes, spaces, reads, meaning},
    G2D_ELEMENT_FACTS(G2D_FACT_ENTRY)
#undef G2D_FACT_ENTRY
};

}  // namespace

const ElementFactEntry* elementFactEntries(std::size_t& count) {
    count = sizeof kFacts / sizeof kFacts[0];
    return kFacts;
}

const ElementFactEntry& elementFactEntry(ElemFact id) { return kFacts[static_cast<std::size_t>(id)]; }

Value elementFact(const Graph& g, ElemClass cls, std::uint32_t id, ElemFact f) {
    switch (f) {
#define G2D_FACT_CASE(fid, fn, name, type, typeName, classes, spaces, reads, meaning) \
    case ElemFact::fid: return Value{fact::fn(g, cls, id)};
        G2D_ELEMENT_FACTS(G2D_FACT_CASE)
#undef G2D_FACT_CASE
    }
    return Value{0LL};
}

}  // namespace g2d::rt
