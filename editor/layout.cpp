#include "editor/layout.h"

#include <algorithm>
#include <vector>

namespace lg::editor {

namespace {

constexpr double column_gap = 90, row_gap = 36;

// Longest path from a source, by depth-first search; an edge back to a node on the current
// path (a history link) is skipped.
struct Depths {
  const Graph& graph;
  std::map<std::string, std::vector<std::string>> inputs;  // node -> nodes feeding it
  std::map<std::string, int> depth;
  std::map<std::string, bool> on_path;

  int of(const std::string& id) {
    if (auto it = depth.find(id); it != depth.end()) return it->second;
    on_path[id] = true;
    int d = 0;
    for (const std::string& from : inputs[id])
      if (!on_path[from] && from != id) d = std::max(d, of(from) + 1);
    on_path[id] = false;
    return depth[id] = d;
  }
};

}  // namespace

std::map<std::string, Position> layered_layout(const Graph& graph, const NodeSize& size) {
  Depths depths{graph, {}, {}, {}};
  for (const GraphLink& l : graph.links) depths.inputs[l.to.node].push_back(l.from.node);

  std::vector<std::vector<std::string>> columns;
  for (const GraphNode& n : graph.nodes) {
    const int d = depths.of(n.id);
    if (int(columns.size()) <= d) columns.resize(d + 1);
    columns[d].push_back(n.id);
  }

  std::map<std::string, Position> placed;
  std::map<std::string, double> centre_y;
  double x = 0;
  for (auto& column : columns) {
    // Barycentre of the already placed inputs; nodes without any keep file order.
    std::map<std::string, double> key;
    for (size_t i = 0; i < column.size(); ++i) {
      double sum = 0;
      int count = 0;
      for (const std::string& from : depths.inputs[column[i]])
        if (auto it = centre_y.find(from); it != centre_y.end()) sum += it->second, ++count;
      key[column[i]] = count ? sum / count : 1e9 + double(i);
    }
    std::stable_sort(column.begin(), column.end(), [&](auto& a, auto& b) { return key[a] < key[b]; });

    double height = 0, width = 0;
    for (const std::string& id : column) height += size(id)[1] + row_gap, width = std::max(width, size(id)[0]);
    double y = -height / 2;
    for (const std::string& id : column) {
      placed[id] = {x, y};
      centre_y[id] = y + size(id)[1] / 2;
      y += size(id)[1] + row_gap;
    }
    x += width + column_gap;
  }
  return placed;
}

}  // namespace lg::editor
