#include "graph/compiler/specialize.h"

namespace lg {

bool input_fed(const ResolvedGraph& resolved, const NodeStates& states, int n, int input) {
  const int li = resolved.nodes[n].input_link[input];
  if (li < 0) return false;
  const ResolvedLink& l = resolved.links[li];
  if (states[l.from_node].kind != NodeState::Kind::bypassed) return true;
  const BypassRule& rule = resolved.nodes[l.from_node].schema->bypass[states[l.from_node].bypass_rule];
  for (const auto& [out, in] : rule.forward)
    if (out == l.from_port) return in >= 0;
  return true;
}

bool condition_holds(const Condition& c, const ResolvedGraph& resolved, const NodeStates& states, int n,
                     const SceneSummary& scene) {
  const ResolvedNode& node = resolved.nodes[n];
  for (int input : c.unless_linked)
    if (input_fed(resolved, states, n, input)) return false;
  switch (c.kind) {
    case Condition::Kind::scene_lacks:
      return !scene.has(c.feature);
    case Condition::Kind::param_equals:
      return node.param(c.param) == c.value;
    case Condition::Kind::param_at_most:
      return node.param(c.param).is_number() && c.value.is_number() &&
             node.param(c.param).as_number() <= c.value.as_number();
  }
  return false;
}

namespace {

// The first bypass rule of node `n` that holds, or -1.
int bypass_rule(const ResolvedGraph& resolved, const NodeStates& states, int n, const SceneSummary& scene) {
  const NodeSchema& s = *resolved.nodes[n].schema;
  for (size_t r = 0; r < s.bypass.size(); ++r)
    if (condition_holds(s.bypass[r].when, resolved, states, n, scene)) return static_cast<int>(r);
  return -1;
}

}  // namespace

NodeStates specialize(const ResolvedGraph& resolved, const SceneSummary& scene) {
  NodeStates states(resolved.nodes.size());
  bool depends_on_links = false;  // a rule "unless_linked": its node waits for its producers' states
  for (size_t n = 0; n < resolved.nodes.size(); ++n) {
    const ResolvedNode& node = resolved.nodes[n];
    NodeState& state = states[n];
    const NodeSchema& s = *node.schema;
    for (const BypassRule& rule : s.bypass) depends_on_links |= !rule.when.unless_linked.empty();
    if (int r = bypass_rule(resolved, states, static_cast<int>(n), scene); r >= 0) {
      state.kind = NodeState::Kind::bypassed;
      state.bypass_rule = r;
      state.reason = s.bypass[r].reason;
    }
    for (size_t p = 0; p < s.passes.size(); ++p) {
      if (!s.passes[p].needs || scene.has(*s.passes[p].needs)) continue;
      state.dropped_passes.resize(s.passes.size());  // only for nodes that drop a pass
      state.dropped_passes[p] = scene_lacks_reason(*s.passes[p].needs);
    }
  }
  // Producers may come after their consumers in the file: settle such rules again until nothing
  // changes (a chain of them takes one round per link; the graph is acyclic but for history
  // links, and the cap keeps a history loop from flipping forever).
  size_t rounds = 0;
  for (bool changed = depends_on_links; changed && rounds <= resolved.nodes.size(); ++rounds) {
    changed = false;
    for (size_t n = 0; n < resolved.nodes.size(); ++n) {
      const NodeSchema& s = *resolved.nodes[n].schema;
      const int r = bypass_rule(resolved, states, static_cast<int>(n), scene);
      const NodeState::Kind kind = r >= 0 ? NodeState::Kind::bypassed : NodeState::Kind::active;
      if (kind == states[n].kind && r == states[n].bypass_rule) continue;
      changed = true;
      states[n].kind = kind;
      states[n].bypass_rule = r;
      states[n].reason = r >= 0 ? s.bypass[r].reason : std::string();
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
