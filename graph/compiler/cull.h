// Phase 5, cull: keeps only what an output needs. Roots are the file's "outputs" and every
// output node; a bypassed node passes liveness on through the inputs it forwards only. Culled
// nodes get a reason naming why nothing needs them.
#pragma once

#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"

namespace lg {

NodeStates cull(const ResolvedGraph& resolved, NodeStates states);

// The input index a bypassed node forwards to its output `port`.
int forwarded_input(const ResolvedGraph& resolved, const NodeStates& states, int node, int port);

}  // namespace lg
