// Phase 4, specialize: fits the graph to a scene. A node whose bypass rule holds (the scene
// lacks what it needs, or a param makes it a no-op) forwards its inputs to its outputs; a pass
// whose scene feature is absent is dropped. Each decision carries its reason into the plan.
#pragma once

#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/json_value.h"
#include "graph/scene_summary.h"

namespace lg {

NodeStates specialize(const ResolvedGraph& resolved, const SceneSummary& scene);
JsonValue dump_node_states(const ResolvedGraph& resolved, const NodeStates& states);

}  // namespace lg
