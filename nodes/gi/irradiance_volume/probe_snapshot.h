// A copy of the probes gi.irradiance_volume's kernel holds now, for a tool that shows them while
// the graph runs (the editor's inspector): the probes the lookup reads, after the last bake or, in
// the dynamic mode, after the last batch of updates that landed. The executor owns kernels; a
// caller that has one asks it through this interface (dynamic_cast from NodeKernel), between
// frames and on the thread that records them, which is the only thread that changes the probes.
#pragma once

#include <cstdint>

#include "nodes/gi/probes/probe_file.h"

namespace lg {

struct ProbeSnapshot {
  // Different for every set of probes any kernel uploads (a process-wide count), so a copy made
  // earlier tells whether it is still current.
  uint64_t version = 0;
  bool dynamic = false;         // the mode: dynamic probes change without an edit
  uint64_t batches_landed = 0;  // dynamic: batches of updates uploaded since the last full bake
  ProbeFile file;               // a whole bake: the volumes, the bake's settings and every probe
};

class ProbeSnapshotSource {
 public:
  virtual ~ProbeSnapshotSource() = default;
  // The version a snapshot would have now; 0 before the first frame has put probes on the device.
  virtual uint64_t probe_version() const = 0;
  // A copy of the current probes (the file's scene, graph, environment and geometry hash empty).
  virtual ProbeSnapshot probe_snapshot() const = 0;
};

}  // namespace lg
