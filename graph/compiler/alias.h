// Phase 9, alias: places resources in memory blocks. Transient and exported resources share
// block 0: resources whose lifetimes do not overlap may share bytes (greedy by size, best-fit
// gap). Cached and history resources keep their own bytes in block 1. Each placement records
// the resources that last held its bytes, which the synchronize phase must wait for.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

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
  std::vector<int> predecessors;          // resources that last held these bytes
};

struct MemoryLayout {
  std::vector<MemoryBlock> blocks;  // [0] frame-transient, [1] persistent
  std::vector<Placement> placements;
};

MemoryLayout alias(const LoweredGraph& lowered, const std::vector<Lifetime>& lifetimes, const AliasOptions& options);
JsonValue dump_memory(const LoweredGraph& lowered, const MemoryLayout& memory);

}  // namespace lg
