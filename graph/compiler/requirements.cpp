#include "graph/compiler/requirements.h"

#include "graph/compiler/specialize.h"

namespace lg {
namespace {

// "'sh' or 'irradiance'".
std::string input_names(const NodeSchema& schema, const std::vector<int>& inputs) {
  std::string names;
  for (size_t i = 0; i < inputs.size(); ++i)
    names += (i == 0 ? "" : i + 1 == inputs.size() ? " or " : ", ") + ("'" + schema.inputs[inputs[i]].name + "'");
  return names;
}

}  // namespace

void check_requirements(const ResolvedGraph& resolved, const NodeStates& states, const SceneSummary& scene,
                        Diagnostics& diagnostics) {
  for (size_t n = 0; n < resolved.nodes.size(); ++n) {
    if (states[n].kind != NodeState::Kind::active) continue;
    const int node = static_cast<int>(n);
    const NodeSchema& schema = *resolved.nodes[n].schema;
    for (const LinkRequirement& req : schema.requires_linked) {
      if (req.when && !condition_holds(*req.when, resolved, states, node, scene)) continue;
      if (req.scene_has && !scene.has(*req.scene_has)) continue;
      for (const std::vector<int>& group : req.linked) {
        bool fed = false;
        for (int input : group) fed |= input_fed(resolved, states, node, input);
        if (fed) continue;
        const GraphNode& gn = resolved.graph->nodes[n];
        diagnostics.error(gn.pos, json_pointer_append("/nodes", n),
                          "node '" + gn.id + "' (" + schema.type + ") needs " +
                              (group.size() > 1 ? "one of its inputs " : "its input ") + input_names(schema, group) +
                              " linked to something that runs: " + req.reason);
      }
    }
  }
}

}  // namespace lg
