#include "editor/preview_ports.h"

namespace lg::editor {

std::vector<PreviewPort> preview_ports(const Graph& graph, const Registry& registry) {
  std::vector<PreviewPort> ports{PreviewPort{}};
  for (const GraphNode& node : graph.nodes) {
    const NodeSchema* schema = registry.find(node.type);
    if (!schema) continue;
    for (const PortSpec& out : schema->outputs) {
      const PortRef ref{node.id, out.name};
      const std::vector<PortComponent>& parts = out.type.components();
      if (parts.size() == 1)
        ports.push_back({ref.text(), ref, 0});
      else
        for (size_t c = 0; c < parts.size(); ++c) ports.push_back({ref.text() + '.' + parts[c].name, ref, int(c)});
    }
  }
  return ports;
}

}  // namespace lg::editor
