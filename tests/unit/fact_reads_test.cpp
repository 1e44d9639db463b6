// Every element fact's `reads` bits (g2d/element_facts.hpp) decide what the
// lowering knows of a rule reading it: the test walks the runtime's fact
// table, so a new fact is covered by its row alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "g2d/element_facts.hpp"
#include "lower/rule_facts.hpp"
#include "test_helpers.hpp"

using namespace g2d;

namespace {

// A condition reading fact `e` of element `var`, whatever its type.
std::string condition(const rt::ElementFactEntry& e, const std::string& var) {
    const std::string read = var + "." + e.name;
    const std::string type = e.typeName;
    if (type == "int") return read + " >= 0";
    if (type == "float") return read + " >= 0.0";
    return read + ".x >= 0.0";
}

std::string grammar(const rt::ElementFactEntry& e, rt::ElemClass cls, bool space3d) {
    std::string g = space3d ? "space 3d;\n" : "";
    g += "node A;\nnode B;\nedge E;\nedge F;\nface Q;\nface R;\naxiom { a: A; }\n";
    if (cls == rt::ElemClass::Node) g += "rule Reads { match { n: A where " + condition(e, "n") + "; } produce { n; } }\n";
    if (cls == rt::ElemClass::Edge)
        g += "rule Reads { match { a: A; b: A; e: a -[E]- b where " + condition(e, "e") + "; } produce { a; b; e; } }\n";
    if (cls == rt::ElemClass::Face) g += "rule Reads { match { f: Q where " + condition(e, "f") + "; } produce { f; } }\n";
    return g;
}

int kindIndex(const ir::Program& p, const std::string& name) {
    for (std::size_t k = 0; k < p.kinds.size(); ++k)
        if (p.kinds[k].name == name) return static_cast<int>(k);
    return -1;
}

bool has(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

TEST_CASE("what a rule reading a fact must see follows the fact table's reads bits", "[ir][incremental]") {
    std::size_t count = 0;
    const rt::ElementFactEntry* entries = rt::elementFactEntries(count);
    int checked = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const rt::ElementFactEntry& e = entries[i];
        for (rt::ElemClass cls : {rt::ElemClass::Node, rt::ElemClass::Edge, rt::ElemClass::Face}) {
            if (!(e.classes & rt::classBit(cls))) continue;
            for (bool space3d : {false, true}) {
                if (!(e.spaces & (space3d ? rt::kIn3d : rt::kIn2d))) continue;
                const std::string text = grammar(e, cls, space3d);
                INFO(text);
                auto r = test::compile(text);
                REQUIRE(test::firstError(r) == "");
                const ir::Program& p = *r.program;
                const rt::RuleInfo info = lower::ruleFacts(p, p.rules[0]).info;
                const bool edgesAt = e.reads & rt::kReadsEdgesAt;
                const bool facesCounted = e.reads & (rt::kReadsFacesAt | rt::kReadsFaceSides);
                CHECK(p.tracksGenerations == bool(e.reads & rt::kReadsGenerations));
                CHECK(info.readsNeighbours == bool(e.reads & rt::kReadsFaceSides));
                // Faces counted: every face kind and every node kind are read.
                CHECK(has(info.readKinds, kindIndex(p, "R")) == facesCounted);
                if (cls == rt::ElemClass::Face) continue;   // a face pattern reads degrees anyway
                CHECK(info.readsDegrees == (edgesAt || facesCounted));
                CHECK(has(info.readKinds, kindIndex(p, "F")) == (edgesAt || facesCounted));
                // Degrees read every edge at the node (an edge's: at its ends).
                const rt::Incidence expected = edgesAt ? rt::Incidence::AllEdges
                                               : cls == rt::ElemClass::Edge ? rt::Incidence::PatternEdges
                                                                            : rt::Incidence::None;
                REQUIRE_FALSE(info.readsIncidence.empty());
                CHECK(info.readsIncidence[0] == expected);
                ++checked;
            }
        }
    }
    CHECK(checked > 20);
}
