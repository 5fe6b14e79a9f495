// Phase 9, alias: places resources in memory blocks. Transient and exported resources share
// block 0: resources whose lifetimes do not overlap may share bytes (greedy by size, best-fit
// gap). Cached and history resources keep their own bytes in block 1. Each placement records
// the resources that last held its bytes, which the synchronize phase must wait for.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "graph/block_cache.h"
#include "graph/compiler/lifetimes.h"
#include "graph/compiler/lowered_graph.h"

namespace lg {

// Bytes and alignment a resource takes in device memory.
struct ResourceMemory {
  uint64_t bytes = 0;
  uint64_t alignment = 1;
};

struct AliasOptions {
  bool enabled = true;
  uint64_t image_alignment = 4096;
  uint64_t buffer_alignment = 256;
  // What the device needs for a resource (drivers pad images: tiles, mip tails), so that
  // placements hold what the runtime binds there. Empty: the resource's own `bytes` and the
  // alignments above. The runtime provides one (runtime/gpu/plan_resources.h); graph/ stays
  // free of Vulkan.
  std::function<ResourceMemory(const LoweredResource&)> memory{};
};

struct MemoryBlock {
  uint64_t size = 0;
  bool aliased = false;  // resources inside may share bytes
};

struct Placement {
  int block = -1;  // -1: not placed (no pass touches the resource)
  uint64_t offset = 0;
  uint64_t size = 0;                      // bytes reserved (the resource's size)
  // The resources that last held these bytes: a run of the layout's (or plan's) predecessor
  // list, as one list for all placements costs one allocation, not one per resource.
  uint32_t first_predecessor = 0, predecessor_count = 0;
};

// The run of `list` a placement's predecessors occupy.
inline std::span<const int> predecessors_in(const CachedVector<int>& list, const Placement& p) {
  return {list.data() + p.first_predecessor, p.predecessor_count};
}

struct MemoryLayout {
  std::vector<MemoryBlock> blocks;  // [0] frame-transient, [1] persistent
  CachedVector<Placement> placements;
  CachedVector<int> predecessors;  // every placement's, back to back
  std::span<const int> predecessors_of(int resource) const {
    return predecessors_in(predecessors, placements[resource]);
  }
};

MemoryLayout alias(const LoweredGraph& lowered, const CachedVector<Lifetime>& lifetimes, const AliasOptions& options);
JsonValue dump_memory(const LoweredGraph& lowered, const MemoryLayout& memory);

}  // namespace lg
