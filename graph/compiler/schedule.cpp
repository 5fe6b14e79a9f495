#include "graph/compiler/schedule.h"

#include <algorithm>

namespace lg {

std::vector<std::vector<int>> pass_dependencies(const LoweredGraph& lowered) {
  const int count = static_cast<int>(lowered.passes.size());
  std::vector<std::vector<int>> before(count);
  std::vector<int> last_writer(lowered.resources.size(), -1);
  std::vector<std::vector<int>> readers(lowered.resources.size());
  auto depend = [&](int p, int on) {
    if (on >= 0 && on != p) before[p].push_back(on);
  };
  for (int p = 0; p < count; ++p) {
    for (const auto& a : lowered.passes[p].accesses) {
      if (usage_reads(a.usage)) depend(p, last_writer[a.resource]);
      if (!usage_writes(a.usage)) {
        readers[a.resource].push_back(p);
        continue;
      }
      depend(p, last_writer[a.resource]);
      for (int r : readers[a.resource]) depend(p, r);
      readers[a.resource].clear();
      last_writer[a.resource] = p;
    }
  }
  return before;
}

std::vector<int> schedule(const LoweredGraph& lowered) {
  const int count = static_cast<int>(lowered.passes.size());
  std::vector<std::vector<int>> before = pass_dependencies(lowered);
  std::vector<char> needed(count, 0);
  for (const auto& list : before)
    for (int p : list) needed[p] = 1;
  // Visit the deepest producer first (as Sethi and Ullman order register allocation): a long
  // chain runs before the short side branches that join it, so their results do not wait
  // through the whole chain. Lowering order is topological, so one forward pass finds depths.
  std::vector<int> depth(count, 0);
  for (int p = 0; p < count; ++p)
    for (int q : before[p]) depth[p] = std::max(depth[p], depth[q] + 1);
  for (auto& list : before)
    std::stable_sort(list.begin(), list.end(), [&](int a, int b) { return depth[a] > depth[b]; });

  // Iterative post-order (graphs may be chains of 10,000 passes).
  std::vector<int> order;
  order.reserve(count);
  std::vector<char> visited(count, 0);
  std::vector<std::pair<int, size_t>> stack;
  for (int sink = 0; sink < count; ++sink) {
    if (needed[sink]) continue;
    stack.emplace_back(sink, 0);
    visited[sink] = 1;
    while (!stack.empty()) {
      auto& [p, next] = stack.back();
      if (next < before[p].size()) {
        int q = before[p][next++];
        if (!visited[q]) {
          visited[q] = 1;
          stack.emplace_back(q, 0);
        }
        continue;
      }
      order.push_back(p);
      stack.pop_back();
    }
  }
  std::stable_partition(order.begin(), order.end(), [&](int p) { return lowered.passes[p].is_static; });
  return order;
}

JsonValue dump_schedule(const LoweredGraph& lowered, const std::vector<int>& order) {
  JsonValue out = JsonValue::array();
  for (int p : order) out.push(lowered.passes[p].name);
  return out;
}

}  // namespace lg
