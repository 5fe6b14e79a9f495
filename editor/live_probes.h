// The live volumes of the editor's preview: after each frame, on the thread that renders, a copy
// of the probes of every gi.irradiance_volume node of the plan (probe_snapshot.h), named after
// the preview's scene and graph so that it saves as a .lgprobes file like a bake's. A node's copy
// is made again only when its probes changed since the last frame; otherwise the same shared,
// immutable snapshot goes on, so the UI thread can tell a change by the pointer or the version.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "nodes/gi/irradiance_volume/probe_snapshot.h"

namespace lg {
class Executor;
}

namespace lg::editor {

using LiveProbes = std::map<std::string, std::shared_ptr<const ProbeSnapshot>>;  // by node id

class LiveProbeCollector {
 public:
  // `identity`: scene, graph, environment and geometry hash for every snapshot's file header.
  LiveProbes collect(const Executor& executor, const ProbeFileHeader& identity);

 private:
  LiveProbes last_;
};

}  // namespace lg::editor
