// Phase 10, synchronize: the barriers the schedule needs. Per resource, its accesses in
// schedule order form groups: a run of reads in one layout, or a single write. Exactly one
// barrier separates consecutive groups (read after write, write after read, write after write,
// or a layout change between reads), and one precedes the first group of an image (its layout
// transition, waiting for whatever held its bytes before: an aliased resource, or the other
// half of a history pair). A previous-frame copy whose last access last frame was a read in
// the layout it is now read in needs no barrier at all.
#pragma once

#include "graph/block_cache.h"
#include "graph/compiler/alias.h"
#include "graph/compiler/barrier.h"
#include "graph/compiler/lowered_graph.h"

namespace lg {

// Stages, access and layout of one use of a resource by a pass.
struct AccessInfo {
  uint32_t stages = 0, access = 0;
  Layout layout = Layout::none;
  bool writes = false;
};
AccessInfo access_info(Usage usage, Queue queue, const LoweredResource& resource);

CachedVector<Barrier> synchronize(const LoweredGraph& lowered, const CachedVector<int>& order,
                                  const MemoryLayout& memory);

JsonValue dump_barriers(const LoweredGraph& lowered, const CachedVector<int>& order,
                        const CachedVector<Barrier>& barriers);

}  // namespace lg
