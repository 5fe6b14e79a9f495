// The ports the preview can show: "main output" first, then every output port of the graph's
// nodes as node.port, a bundle's components as node.port.component (gbuf.gbuffer.normal).
#pragma once

#include <vector>

#include "editor/preview.h"
#include "graph/registry.h"

namespace lg::editor {

// Nodes of unknown types have no ports here (the graph does not compile anyway).
std::vector<PreviewPort> preview_ports(const Graph& graph, const Registry& registry);

}  // namespace lg::editor
