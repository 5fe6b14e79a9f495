// IR after phase 2 (resolve): every node bound to its schema, every link to port indices,
// params filled in with their defaults. Indices refer to Graph::nodes and schema port lists.
#pragma once

#include <vector>

#include "graph/graph.h"
#include "graph/schema.h"

namespace lg {

struct ResolvedLink {
  int from_node = -1, from_port = -1;  // output port index
  int to_node = -1, to_port = -1;      // input port index
  int source = -1;                     // index into Graph::links
  bool history = false;                // into a history input: reads the previous frame
};

struct ResolvedNode {
  const NodeSchema* schema = nullptr;  // null when the type is unknown (already reported)
  std::vector<JsonValue> params;       // one per schema param, defaults filled in
  std::vector<int> input_link;         // per schema input: index into links, or -1
};

struct ResolvedGraph {
  const Graph* graph = nullptr;
  std::vector<ResolvedNode> nodes;
  std::vector<ResolvedLink> links;
  std::vector<std::pair<int, int>> outputs;  // (node, output port) requested by the file

  int link_into(int node, int input) const { return nodes[node].input_link[input]; }
};

}  // namespace lg
