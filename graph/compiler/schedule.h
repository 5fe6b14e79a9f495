// Phase 7, schedule: orders the passes. The order is a depth-first post-order of the pass
// dependencies, walked back from the passes nothing depends on, deepest producer first: each
// producer runs just before the consumer that first needs it, which keeps resources
// short-lived and lets the alias phase share more memory. Static passes are hoisted to the front (they depend only on
// each other), so a frame whose cached results are valid skips one contiguous prefix. The
// order depends only on lowering order, which does not depend on the order of the file.
#pragma once

#include <vector>

#include "graph/compiler/lowered_graph.h"

namespace lg {

// Pass indices (into LoweredGraph::passes) in execution order.
std::vector<int> schedule(const LoweredGraph& lowered);

// For each pass, the passes it must follow: the writer of what it reads, and the readers and
// writer before it of what it writes.
std::vector<std::vector<int>> pass_dependencies(const LoweredGraph& lowered);

JsonValue dump_schedule(const LoweredGraph& lowered, const std::vector<int>& order);

}  // namespace lg
