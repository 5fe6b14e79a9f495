// Phase 8, lifetimes: the first and last scheduled pass that touches each resource. Results of
// the frame live to its end; cached and history resources live across frames.
#pragma once

#include "graph/block_cache.h"
#include "graph/compiler/lowered_graph.h"

namespace lg {

struct Lifetime {
  int first = -1, last = -1;  // positions in the schedule; -1 when no pass touches it
  bool used() const { return first >= 0; }
};

CachedVector<Lifetime> lifetimes(const LoweredGraph& lowered, const CachedVector<int>& order);

JsonValue dump_lifetimes(const LoweredGraph& lowered, const CachedVector<Lifetime>& lifetimes);

}  // namespace lg
