// rt::eachRuleInfoField must name every field of rt::RuleInfo: the emitter
// prints a rule's info from that list, so a field missing there would be
// left at its default in compiled grammars only.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "g2d/rule_info.hpp"

namespace {

// Converts to any field type: an aggregate can be brace-initialised from N of
// these exactly when it has at least N fields.
struct AnyField {
    template <class T>
    operator T() const;
};

template <class T, class... Fields>
constexpr std::size_t aggregateFieldCount() {
    if constexpr (requires { T{Fields{}..., AnyField{}}; }) return aggregateFieldCount<T, Fields..., AnyField>();
    else return sizeof...(Fields);
}

}  // namespace

TEST_CASE("the RuleInfo field list names every field, in order", "[emit][rule_info]") {
    std::vector<std::string> names;
    g2d::rt::RuleInfo info;
    g2d::rt::eachRuleInfoField(info, [&](const char* name, auto&) { names.emplace_back(name); });
    CHECK(names.size() == aggregateFieldCount<g2d::rt::RuleInfo>());
    // Each visited reference is a distinct member, in declaration order.
    std::vector<const char*> addresses;
    g2d::rt::eachRuleInfoField(info, [&](const char*, auto& field) { addresses.push_back(reinterpret_cast<const char*>(&field)); });
    for (std::size_t i = 1; i < addresses.size(); ++i) CHECK(addresses[i - 1] < addresses[i]);
}
