#include "front/reserved_names.hpp"

#include "parse/keywords.hpp"
#include "sema/builtins.hpp"
#include "sema/decl_checker.hpp"
#include "sema/element_facts.hpp"

namespace g2d::front {

const std::vector<std::string>& keywords() { return parse::keywords(); }

const std::set<std::string>& keywordNames() {
    static const std::set<std::string> names(parse::keywords().begin(), parse::keywords().end());
    return names;
}

const std::set<std::string>& reservedNames() {
    static const std::set<std::string> names = [] {
        std::set<std::string> out(parse::keywords().begin(), parse::keywords().end());
        out.insert(sema::valueTypeNames().begin(), sema::valueTypeNames().end());
        for (const auto& b : sema::builtinFunctions()) out.insert(b.name);
        for (const auto& f : sema::elementFacts()) out.insert(f.name);
        for (const char* constant : {"pi", "tau", "placed"}) out.insert(constant);   // sema's expression checker knows these
        return out;
    }();
    return names;
}

const std::set<std::string>& attributeNamesRefused() {
    static const std::set<std::string> names = [] {
        std::set<std::string> out(parse::keywords().begin(), parse::keywords().end());
        out.insert(sema::reservedAttributeNames().begin(), sema::reservedAttributeNames().end());
        return out;
    }();
    return names;
}

}  // namespace g2d::front
