// Phase 4, specialize: fits the graph to a scene. A node whose bypass rule holds (the scene
// lacks what it needs, or a param makes it a no-op) forwards its inputs to its outputs; a pass
// whose scene feature is absent is dropped. Each decision carries its reason into the plan.
#pragma once

#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/json_value.h"
#include "graph/scene_summary.h"

namespace lg {

// Whether input `input` of node `n` gets something: it is linked, and not to a bypassed node
// whose rule forwards nothing (null) to that output.
bool input_fed(const ResolvedGraph& resolved, const NodeStates& states, int n, int input);
// Whether a bypass's or a requirement's condition holds for node `n` in `scene`.
bool condition_holds(const Condition& c, const ResolvedGraph& resolved, const NodeStates& states, int n,
                     const SceneSummary& scene);

NodeStates specialize(const ResolvedGraph& resolved, const SceneSummary& scene);
JsonValue dump_node_states(const ResolvedGraph& resolved, const NodeStates& states);

}  // namespace lg
