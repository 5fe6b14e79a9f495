// The last step: gathers every phase's result into the Plan, plain data that owns its strings
// and needs neither the graph nor the registry to be read.
#pragma once

#include <string>

#include "graph/asset_paths.h"
#include "graph/block_cache.h"
#include "graph/compiler/alias.h"
#include "graph/compiler/barrier.h"
#include "graph/compiler/lifetimes.h"
#include "graph/compiler/lower.h"
#include "graph/compiler/node_states.h"
#include "graph/compiler/resolved_graph.h"
#include "graph/plan.h"

namespace lg {

struct AssembleOptions {
  std::string scene_name;
  FrameSize frame;
  AssetRoots roots;  // to make path params absolute
  bool keeps_every_output = false;  // Plan::keeps_every_output
};

// Takes over what the plan keeps of the IRs passed as rvalues (names, reasons, placements)
// rather than copying it.
Plan assemble(const Graph& graph, const ResolvedGraph& resolved, NodeStates&& states, LoweredGraph&& lowered,
              const CachedVector<int>& node_order, const CachedVector<int>& order, const CachedVector<Lifetime>& lives,
              MemoryLayout&& memory, CachedVector<Barrier> barriers, const AssembleOptions& options);

}  // namespace lg
