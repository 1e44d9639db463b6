#pragma once
// What the imported grammar's one node kind and one edge kind hold: every
// attribute the tool's elements carry, with the g2d type its values and
// expressions agree on, and which of them must remember being set at all.

#include <set>
#include <string>
#include <vector>

#include "import/python_expr.hpp"

namespace g2d::import {

struct CatalogueAttribute {
    std::string key;           // the tool's key; "svg_<prop>" for a style property that is read
    PyType type = PyType::Unknown;
    bool usedInCondition = false;
    bool setEverywhere = true; // every host element and every new element sets it
    bool conditionFalseOnDefault = false;   // e.g. attr=='Wall': an unset "" never matches
    // The tool's condition also asks that the key exist: the name of the
    // flag attribute that remembers it was set ("" for none; presenceFlags).
    std::string presence;
};

struct KindCatalogue {
    bool isNode = true;
    std::vector<CatalogueAttribute> attributes;
    std::set<std::string> readStyles;   // style properties read back (kept as svg_<prop>)
    bool tagVaries = false;             // some element is drawn as a rect, path, … (tagAttribute)
    // The attribute holding the tool's .svg_tag when it varies: `svg_tag`,
    // numbered on when an element carries a key of that name.
    std::string tagAttribute = "svg_tag";

    CatalogueAttribute* find(const std::string& key) {
        for (auto& a : attributes) if (a.key == key) return &a;
        return nullptr;
    }
    const CatalogueAttribute* find(const std::string& key) const {
        for (const auto& a : attributes) if (a.key == key) return &a;
        return nullptr;
    }
    CatalogueAttribute& add(const std::string& key) {
        if (auto* a = find(key)) return *a;
        CatalogueAttribute& a = attributes.emplace_back();
        a.key = key;
        return a;
    }
};

// Names the attributes the importer adds to the tool's keys, none equal to a
// key: the tag attribute, and the flags of the attributes in `needFlag`
// (CatalogueAttribute::presence): `has_grown`, for a key that already says
// so `has_door_set` (not `has_has_door`).
void nameAddedAttributes(KindCatalogue& kind, const std::set<std::string>& needFlag);

// Int and Float make Float, Bool and a number the number; a String and
// anything else String (conflict set).
PyType mergeTypes(PyType a, PyType b, bool& conflict);

// g2d's name of a type, and a literal of its default value.
std::string g2dTypeName(PyType type);
std::string defaultLiteral(PyType type);

}  // namespace g2d::import
