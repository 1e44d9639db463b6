#pragma once
// Writes a graph in NetworkX's node-link format (readable by
// networkx.node_link_graph): a directed multigraph whose nodes carry kind,
// pos, age and attributes, and whose links carry source, target, key, kind,
// directed, age and attributes; faces (when the grammar has face kinds)
// carry id, kind, corners, holes (if any: rings of node ids inside the face
// that it does not cover), age and attributes. Numbers print as the shortest round-trip
// decimal, so every back end writes the same bytes.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "g2d/graph.hpp"
#include "g2d/json_schema.hpp"
#include "g2d/text_out.hpp"

namespace g2d::rt {

// Reads attribute `attr` of a node or edge (back ends store them their own way).
using AttributeReader = std::function<Value(ElemClass cls, std::uint32_t id, int attr)>;

// `graphAttrs` become the "graph" object (e.g. steps, seed). Without a reader,
// attributes are read from the graph's own slots.
std::string writeJson(const Graph& g, const JsonSchema& schema,
                      const std::vector<std::pair<std::string, Value>>& graphAttrs,
                      const AttributeReader& attr = {});
// The same text, streamed into `out`.
void writeJson(const Graph& g, const JsonSchema& schema, const std::vector<std::pair<std::string, Value>>& graphAttrs,
               TextOut& out, const AttributeReader& attr = {});

std::string jsonString(const std::string& s);

}  // namespace g2d::rt
