#include "graph/compiler/cull.h"

#include <algorithm>
#include <string_view>

namespace lg {

int forwarded_input(const ResolvedGraph& resolved, const NodeStates& states, int node, int port) {
  const BypassRule& rule = resolved.nodes[node].schema->bypass[states[node].bypass_rule];
  for (const auto& [out, in] : rule.forward)
    if (out == port) return in;
  return -1;
}

NodeStates cull(const ResolvedGraph& resolved, NodeStates states) {
  const size_t count = resolved.nodes.size();
  CachedVector<char> live(count, 0);
  CachedVector<int> stack;
  auto visit = [&](int n) {
    if (!live[n]) live[n] = 1, stack.push_back(n);
  };
  for (const auto& [node, port] : resolved.outputs) visit(node);
  for (size_t n = 0; n < count; ++n)
    if (resolved.nodes[n].schema->is_output) visit(static_cast<int>(n));
  while (!stack.empty()) {
    int n = stack.back();
    stack.pop_back();
    const ResolvedNode& rn = resolved.nodes[n];
    for (size_t i = 0; i < rn.input_link.size(); ++i) {
      int li = rn.input_link[i];
      if (li < 0) continue;
      if (states[n].kind == NodeState::Kind::bypassed) {
        bool forwarded = false;
        for (const auto& [out, in] : rn.schema->bypass[states[n].bypass_rule].forward) forwarded |= in == static_cast<int>(i);
        if (!forwarded) continue;
      }
      visit(resolved.links[li].from_node);
    }
  }
  // Every bypassed node that would have used a dead one, named in id order so the reason does
  // not depend on the order of the file's links.
  CachedVector<std::vector<std::string_view>> bypassed_consumers(count);
  for (const auto& l : resolved.links)
    if (!live[l.from_node] && live[l.to_node] && states[l.to_node].kind == NodeState::Kind::bypassed)
      bypassed_consumers[l.from_node].push_back(resolved.graph->nodes[l.to_node].id);
  for (size_t n = 0; n < count; ++n) {
    if (live[n]) continue;
    states[n].kind = NodeState::Kind::culled;
    auto& consumers = bypassed_consumers[n];
    std::sort(consumers.begin(), consumers.end());
    consumers.erase(std::unique(consumers.begin(), consumers.end()), consumers.end());
    std::string names;
    for (size_t k = 0; k < consumers.size(); ++k)
      names += (k == 0 ? "'" : k + 1 == consumers.size() ? " and '" : ", '") + std::string(consumers[k]) + "'";
    states[n].reason = consumers.empty()      ? "no output depends on it"
                       : consumers.size() == 1 ? "only " + names + " uses it, and that node is bypassed"
                                               : "only " + names + " use it, and those nodes are bypassed";
  }
  return states;
}

}  // namespace lg
