// The graph model: what a graph file says, before anything is checked against the registry.
// Nodes, links between ports ("node.port" strings in the file), requested outputs and the
// editor's free-form metadata. Positions are kept so every later error can point at the source.
#pragma once

#include <string>
#include <vector>

#include "graph/json_value.h"

namespace lg {

inline constexpr const char* graph_format = "lumagraph/1";

struct PortRef {
  std::string node;
  std::string port;
  std::string text() const { return node + '.' + port; }
};

struct GraphNode {
  std::string id;
  std::string type;
  JsonValue params = JsonValue::object();  // as written: defaults are not filled in
  SourcePos pos, type_pos;
};

struct GraphLink {
  PortRef from, to;
  SourcePos from_pos, to_pos;
};

struct GraphOutput {
  PortRef port;
  SourcePos pos;
};

struct Graph {
  std::string file;  // where it was loaded from; relative paths in params resolve against it
  std::string name;
  std::vector<GraphNode> nodes;
  std::vector<GraphLink> links;
  std::vector<GraphOutput> outputs;
  JsonValue editor = JsonValue::object();  // kept as-is: positions, colours, notes, unknown keys
};

}  // namespace lg
