#include "graph/compiler/specialize.h"

namespace lg {
namespace {

bool holds(const Condition& c, const ResolvedNode& node, const SceneSummary& scene) {
  if (c.unless_linked >= 0 && node.input_link[c.unless_linked] >= 0) return false;
  switch (c.kind) {
    case Condition::Kind::scene_lacks: return !scene.has(c.feature);
    case Condition::Kind::param_equals: return node.param(c.param) == c.value;
    case Condition::Kind::param_at_most:
      return node.param(c.param).is_number() && c.value.is_number() &&
             node.param(c.param).as_number() <= c.value.as_number();
  }
  return false;
}

}  // namespace

NodeStates specialize(const ResolvedGraph& resolved, const SceneSummary& scene) {
  NodeStates states(resolved.nodes.size());
  for (size_t n = 0; n < resolved.nodes.size(); ++n) {
    const ResolvedNode& node = resolved.nodes[n];
    NodeState& state = states[n];
    const NodeSchema& s = *node.schema;
    for (size_t r = 0; r < s.bypass.size(); ++r) {
      if (!holds(s.bypass[r].when, node, scene)) continue;
      state.kind = NodeState::Kind::bypassed;
      state.bypass_rule = static_cast<int>(r);
      state.reason = s.bypass[r].reason;
      break;
    }
    for (size_t p = 0; p < s.passes.size(); ++p) {
      if (!s.passes[p].needs || scene.has(*s.passes[p].needs)) continue;
      state.dropped_passes.resize(s.passes.size());  // only for nodes that drop a pass
      state.dropped_passes[p] = scene_lacks_reason(*s.passes[p].needs);
    }
  }
  return states;
}

JsonValue dump_node_states(const ResolvedGraph& resolved, const NodeStates& states) {
  JsonValue out = JsonValue::array();
  for (size_t n = 0; n < states.size(); ++n) {
    JsonValue& node = out.push(JsonValue::object());
    node.set("id", resolved.graph->nodes[n].id);
    node.set("state", std::string(node_state_name(states[n].kind)));
    if (!states[n].reason.empty()) node.set("reason", states[n].reason);
    for (size_t p = 0; p < states[n].dropped_passes.size(); ++p)
      if (!states[n].dropped_passes[p].empty())
        node.set("dropped_" + resolved.nodes[n].schema->passes[p].name, states[n].dropped_passes[p]);
  }
  return out;
}

}  // namespace lg
