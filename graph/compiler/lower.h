// Phase 6, lower: turns each live node into its schema's passes and each port into resources
// sized for the frame. Bypassed nodes become aliases of their inputs; history links get a
// previous-frame copy; static nodes whose inputs are static get a cache key. An optional output
// nothing links nor lists is not written (its accesses dropped) unless keep_optional_outputs.
#pragma once

#include <optional>

#include "graph/asset_paths.h"
#include "graph/block_cache.h"
#include "graph/compiler/lowered_graph.h"
#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/diagnostics.h"

namespace lg {

struct FrameSize {
  uint32_t width = 1280, height = 720;
  friend bool operator==(const FrameSize&, const FrameSize&) = default;
};

std::optional<LoweredGraph> lower(const ResolvedGraph& resolved, const CachedVector<int>& topo_order,
                                  const NodeStates& states, FrameSize frame, const AssetRoots& roots,
                                  Diagnostics& diagnostics, bool keep_optional_outputs = false);
JsonValue dump_lowered(const LoweredGraph& lowered);

// A node's params as the runtime gets them: every param, defaults filled, paths absolute.
JsonValue node_params(const ResolvedGraph& resolved, int node, const AssetRoots& roots);

}  // namespace lg
