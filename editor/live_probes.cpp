#include "editor/live_probes.h"

#include "runtime/exec/executor.h"

namespace lg::editor {

LiveProbes LiveProbeCollector::collect(const Executor& executor, const ProbeFileHeader& identity) {
  LiveProbes now;
  const auto& nodes = executor.plan().nodes;
  for (size_t i = 0; i < nodes.size(); ++i) {
    const auto* source = dynamic_cast<const ProbeSnapshotSource*>(executor.kernel(i));
    if (!source || source->probe_version() == 0) continue;
    const auto kept = last_.find(nodes[i].id);
    if (kept != last_.end() && kept->second->version == source->probe_version()) {
      now.insert(*kept);
      continue;
    }
    auto snapshot = std::make_shared<ProbeSnapshot>(source->probe_snapshot());
    ProbeFileHeader& h = snapshot->file.header;
    h.scene = identity.scene;
    h.graph = identity.graph;
    h.environment = identity.environment;
    h.geometry_hash = identity.geometry_hash;
    now.emplace(nodes[i].id, std::move(snapshot));
  }
  last_ = now;
  return now;
}

}  // namespace lg::editor
