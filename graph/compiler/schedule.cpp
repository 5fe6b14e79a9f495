#include "graph/compiler/schedule.h"

#include <algorithm>

namespace lg {

PassDependencies pass_dependencies(const LoweredGraph& lowered) {
  const int count = static_cast<int>(lowered.passes.size());
  PassDependencies out;
  out.start.reserve(count + 1);
  // Per resource: its last writer, and the passes that read it since, as linked lists in one pool.
  struct Reader {
    int pass, next;
  };
  CachedVector<int> last_writer(lowered.resources.size(), -1), first_reader(lowered.resources.size(), -1);
  CachedVector<Reader> readers;
  // Each access adds at most one reader, and mostly one dependency or none.
  const size_t accesses = lowered.access_count();
  readers.reserve(accesses);
  out.passes.reserve(accesses);
  auto depend = [&](int p, int on) {
    if (on >= 0 && on != p) out.passes.push_back(on);
  };
  for (int p = 0; p < count; ++p) {
    out.start.push_back(static_cast<int>(out.passes.size()));
    for (const auto& a : lowered.passes[p].accesses) {
      if (usage_reads(a.usage)) depend(p, last_writer[a.resource]);
      if (!usage_writes(a.usage)) {
        readers.push_back({p, first_reader[a.resource]});
        first_reader[a.resource] = static_cast<int>(readers.size()) - 1;
        continue;
      }
      depend(p, last_writer[a.resource]);
      for (int r = first_reader[a.resource]; r >= 0; r = readers[r].next) depend(p, readers[r].pass);
      first_reader[a.resource] = -1;
      last_writer[a.resource] = p;
    }
  }
  out.start.push_back(static_cast<int>(out.passes.size()));
  return out;
}

CachedVector<int> schedule(const LoweredGraph& lowered) {
  const int count = static_cast<int>(lowered.passes.size());
  PassDependencies before = pass_dependencies(lowered);
  CachedVector<char> needed(count, 0);
  for (int p : before.passes) needed[p] = 1;
  // Visit the deepest producer first (as Sethi and Ullman order register allocation): a long
  // chain runs before the short side branches that join it, so their results do not wait
  // through the whole chain. Lowering order is topological, so one forward pass finds depths.
  CachedVector<int> depth(count, 0);
  for (int p = 0; p < count; ++p)
    for (int q : before[p]) depth[p] = std::max(depth[p], depth[q] + 1);
  std::vector<std::pair<int, int>> keyed;  // (-depth, place in the list): a stable sort, one buffer
  for (int p = 0; p < count; ++p) {
    std::span<int> list = before[p];
    if (list.size() < 2) continue;  // most passes: nothing to order
    keyed.clear();
    for (size_t k = 0; k < list.size(); ++k) keyed.emplace_back(-depth[list[k]], static_cast<int>(k));
    std::sort(keyed.begin(), keyed.end());
    for (size_t k = 0; k < keyed.size(); ++k) keyed[k].first = list[keyed[k].second];
    for (size_t k = 0; k < keyed.size(); ++k) list[k] = keyed[k].first;
  }

  // Iterative post-order (graphs may be chains of 10,000 passes).
  CachedVector<int> order;
  order.reserve(count);
  CachedVector<char> visited(count, 0);
  CachedVector<std::pair<int, size_t>> stack;
  stack.reserve(count);  // as deep as the longest chain: most of the graph in large ones
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

JsonValue dump_schedule(const LoweredGraph& lowered, const CachedVector<int>& order) {
  JsonValue out = JsonValue::array();
  for (int p : order) out.push(lowered.passes[p].name);
  return out;
}

}  // namespace lg
