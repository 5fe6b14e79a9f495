// The compiler's result, as plain data: passes in execution order with what each reads and
// writes, resources with lifetimes and memory offsets, barriers, cache keys, and every node's
// fate (active, bypassed, culled, passes dropped) with the reason. The runtime executes it;
// plan_format.h prints it as JSON, Graphviz dot and a text table.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "graph/block_cache.h"
#include "graph/compiler/alias.h"
#include "graph/compiler/barrier.h"
#include "graph/compiler/lower.h"
#include "graph/compiler/node_states.h"

namespace lg {

// Members largest first, in each record: no padding between them.
struct PlanNode {
  std::string id, type;
  std::string reason;                                        // bypassed or culled: why
  std::vector<std::pair<std::string, std::string>> dropped;  // (pass, why) for dropped passes
  JsonValue params = JsonValue::object();                    // defaults filled, paths absolute
  NodeState::Kind state = NodeState::Kind::active;
  bool is_static = false;
};

struct PlanAccess {
  int resource = -1;
  Usage usage = Usage::sampled;
  int slot = -1;      // into Plan::slot_names: the node's port or internal resource
  int component = 0;  // within a bundle (G-buffer): index into its components
};

struct PlanPass {
  std::string name;                             // "bloom/downsample"
  std::string pass;                             // "downsample"
  uint64_t cache_key = 0;                       // 0 unless static
  int node = -1;                                // index into Plan::nodes
  uint32_t first_access = 0, access_count = 0;  // its run of Plan::accesses
  Queue queue = Queue::compute;
  bool is_static = false;
};

struct PlanResource {
  LoweredResource desc;
  int first = -1, last = -1;  // schedule positions
  Placement placement;
};

// A result of the frame: what an output node reads, or a port the file lists in "outputs".
struct PlanOutput {
  int node = -1;               // the output node (index into Plan::nodes), or -1 for a file output
  std::string port;            // the port whose resources these are: "tonemap.color"
  std::vector<int> resources;  // one, or a bundle's components
};

struct MemoryTotals {
  uint64_t transient_unaliased = 0;  // one allocation per transient resource
  uint64_t transient = 0;            // block 0 with aliasing
  uint64_t persistent = 0;           // cached and history resources
};

struct Plan {
  std::string name, file, scene;
  FrameSize frame;
  CachedVector<PlanNode> nodes;  // in topological order, ties broken by id
  CachedVector<PlanPass> passes;
  CachedVector<PlanAccess> accesses;  // every pass's, back to back in pass order: one allocation, not one a pass
  CachedVector<PlanResource> resources;
  CachedVector<Barrier> barriers;   // sorted by Barrier::before
  std::vector<PlanOutput> outputs;  // the file's outputs, then output nodes' inputs
  std::vector<MemoryBlock> blocks;
  CachedVector<int> predecessors;  // the placements' predecessor lists, back to back
  // Every slot name the accesses use, once: "in.color", "out.ao", "tmp.chain". A graph of
  // thousands of nodes uses a few dozen.
  std::vector<std::string> slot_names;
  MemoryTotals memory;
  // The pixel grid the camera is jittered on each frame (a node whose schema has
  // "camera_jitter" runs, e.g. post.taa: the extent of the input it names); 0 x 0: no jitter.
  std::array<uint32_t, 2> jitter_grid{0, 0};
  // Compiled with CompileOptions::keep_optional_outputs (a dump): every output is wanted, so a
  // node that skips work for outputs nothing reads does not skip it.
  bool keeps_every_output = false;

  const std::string& slot_of(const PlanAccess& a) const { return slot_names[a.slot]; }
  std::span<const PlanAccess> accesses_of(const PlanPass& p) const { return {accesses.data() + p.first_access, p.access_count}; }

  // The resources that last held resource r's bytes.
  std::span<const int> predecessors_of(int r) const { return predecessors_in(predecessors, resources[r].placement); }
};

}  // namespace lg
