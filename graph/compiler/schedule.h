// Phase 7, schedule: orders the passes. The order is a depth-first post-order of the pass
// dependencies, walked back from the passes nothing depends on, deepest producer first: each
// producer runs just before the consumer that first needs it, which keeps resources
// short-lived and lets the alias phase share more memory. Static passes are hoisted to the front (they depend only on
// each other), so a frame whose cached results are valid skips one contiguous prefix. The
// order depends only on lowering order, which does not depend on the order of the file.
#pragma once

#include <span>

#include "graph/block_cache.h"
#include "graph/compiler/lowered_graph.h"

namespace lg {

// Pass indices (into LoweredGraph::passes) in execution order.
CachedVector<int> schedule(const LoweredGraph& lowered);

// For each pass, the passes it must follow: the writer of what it reads, and the readers and
// writer before it of what it writes. All lists in one array (a pass may list one twice).
struct PassDependencies {
  CachedVector<int> start;  // pass p's list is passes[start[p] .. start[p + 1])
  CachedVector<int> passes;
  std::span<const int> operator[](size_t p) const { return {passes.data() + start[p], passes.data() + start[p + 1]}; }
  std::span<int> operator[](size_t p) { return {passes.data() + start[p], passes.data() + start[p + 1]}; }
};
PassDependencies pass_dependencies(const LoweredGraph& lowered);

JsonValue dump_schedule(const LoweredGraph& lowered, const CachedVector<int>& order);

}  // namespace lg
