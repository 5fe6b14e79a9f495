// After specialization and culling: every active node whose schema requires inputs linked in
// its configuration (NodeSchema::requires_linked: a param's value, a scene feature) gets them,
// or the graph is refused with the node's place in the file, the inputs and why. Such needs
// depend on the scene, so the validate phase, which knows no scene, cannot check them.
#pragma once

#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/diagnostics.h"
#include "graph/scene_summary.h"

namespace lg {

void check_requirements(const ResolvedGraph& resolved, const NodeStates& states, const SceneSummary& scene,
                        Diagnostics& diagnostics);

}  // namespace lg
