// IR after phase 2 (resolve): every node bound to its schema, every link to port indices,
// params filled in with their defaults. Indices refer to Graph::nodes and schema port lists.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/block_cache.h"
#include "graph/graph.h"
#include "graph/schema.h"

namespace lg {

// An input whose link names an unknown node or port: already reported, so the input does
// not also count as missing.
inline constexpr int broken_link = -2;

struct ResolvedLink {
  int from_node = -1, from_port = -1;  // output port index
  int to_node = -1, to_port = -1;      // input port index
  int source = -1;                     // index into Graph::links
  bool history = false;                // into a history input: reads the previous frame
};

// The spans view ResolvedGraph's flat arrays: one allocation per graph, not two per node.
struct ResolvedNode {
  const NodeSchema* schema = nullptr;  // null when the type is unknown (already reported)
  std::span<const JsonValue*> params;  // per schema param: the value written, or the default
  const JsonValue& param(int index) const { return *params[index]; }
  std::span<int> input_link;           // per schema input: index into links, -1 or broken_link
};

struct ResolvedGraph {
  ResolvedGraph() = default;
  ResolvedGraph(ResolvedGraph&&) = default;  // moving keeps the arrays the spans point into
  ResolvedGraph& operator=(ResolvedGraph&&) = default;

  const Graph* graph = nullptr;
  CachedVector<ResolvedNode> nodes;
  CachedVector<const JsonValue*> param_values;  // every node's params, back to back
  CachedVector<int> input_links;                // every node's input links, back to back
  CachedVector<ResolvedLink> links;
  std::vector<std::pair<int, int>> outputs;  // (node, output port) requested by the file
  // Every node's id, back to back, and where each starts (one more entry for the end): later
  // phases read ids from this compact run rather than from the graph's nodes, which large
  // graphs scatter over megabytes.
  std::string id_text;
  CachedVector<uint32_t> id_starts;
  std::string_view id(int node) const {
    return {id_text.data() + id_starts[node], id_starts[node + 1] - id_starts[node]};
  }
};

}  // namespace lg
