// What one frame cost and what the plan left out: GPU time per pass from timestamps (and which
// passes were skipped as cached), CPU time, device memory, and the nodes and passes the
// compiler bypassed, culled or dropped with its reasons. Written as JSON for
// `lumagraph render --stats FILE` and as a text table for people.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "graph/json_value.h"
#include "graph/plan.h"

namespace lg {

struct PassStats {
  std::string name;     // "light/direct"
  double gpu_ms = 0;    // 0 when skipped
  bool cached = false;  // a static pass skipped: its key is unchanged since it last ran
};

struct SkippedNode {
  std::string id, type;
  NodeState::Kind state = NodeState::Kind::bypassed;  // bypassed or culled
  std::string reason;
};

struct DroppedPass {
  std::string pass, type, reason;  // "light/area", "lighting.deferred", why
};

struct FrameStats {
  uint64_t frame = 0;             // 0 for the first frame
  std::vector<PassStats> passes;  // in schedule order
  double gpu_ms = 0;              // the whole command buffer, barriers included
  double cpu_ms = 0;              // recording, submission and the wait for the GPU
  // Context::device_memory_used() at the frame's end, before kernels free what only recording
  // needed (NodeKernel::frame_finished).
  uint64_t device_memory_used = 0;
  MemoryTotals plan_memory;
  std::vector<SkippedNode> skipped_nodes;
  std::vector<DroppedPass> dropped_passes;
};

// The plan's part of the stats: bypassed and culled nodes, dropped passes, memory totals.
FrameStats plan_stats(const Plan& plan);

// "lumagraph-frame-stats/1".
JsonValue frame_stats_json(const FrameStats& stats);
std::string frame_stats_text(const FrameStats& stats);

}  // namespace lg
