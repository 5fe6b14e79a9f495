// Phase 2, resolve: binds node types to schemas, link and output references to ports, and
// param names to schema params (filling defaults). Unknown names are reported with the closest
// known name as a suggestion.
#pragma once

#include "graph/compiler/resolved_graph.h"
#include "graph/diagnostics.h"
#include "graph/registry.h"

namespace lg {

ResolvedGraph resolve(const Graph& graph, const Registry& registry, Diagnostics& diagnostics);
JsonValue dump_resolved(const ResolvedGraph& resolved);

}  // namespace lg
