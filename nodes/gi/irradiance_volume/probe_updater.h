// gi.irradiance_volume's dynamic mode off the frame's thread: one batch of probe updates
// (update_probes(), probe_update.h) at a time runs on a worker thread, which traces with Embree on
// every core. The kernel polls each frame and never waits: a finished batch's probes replace the
// current ones (the kernel uploads them all), and the next batch starts from them with the scene
// as it is then. The worker rebuilds its PathScene only when the scene's probe_bake_key() differs
// from the one it traced last, so a light that moves is picked up by the next batch and the
// probes converge from what they held, over the following batches. After `settle_sweeps` sweeps
// over every probe of an unchanged scene no batch starts until the key changes (0: never pause).
#pragma once

#include <cstdint>
#include <future>
#include <memory>
#include <vector>

#include "nodes/gi/path_tracer/path_scene.h"
#include "nodes/gi/probes/probe_update.h"

namespace lg {

class ProbeUpdater {
 public:
  ProbeUpdater(const ProbeUpdateSettings& settings, uint32_t settle_sweeps)
      : settings_(settings), settle_sweeps_(settle_sweeps) {}
  ProbeUpdater(const ProbeUpdater&) = delete;
  ProbeUpdater& operator=(const ProbeUpdater&) = delete;
  ~ProbeUpdater();  // waits for the batch in flight

  // Starts over from `grids` (a full bake), dropping the batch in flight.
  void reset(std::vector<ProbeGrid> grids);
  bool has_probes() const { return !grids_.empty(); }
  // The current probes: the last reset()'s or the last finished() batch's.
  const std::vector<ProbeGrid>& probes() const { return grids_; }
  bool in_flight() const { return batch_.valid(); }
  // The probes after the batch that has just finished, or null while one is in flight or when
  // none ran since the last call. Rethrows what the batch threw.
  const std::vector<ProbeGrid>* finished();
  // Starts the next batch from the current probes; `key` is probe_bake_key(scene). Does nothing
  // while the probes have settled on this key.
  void start(const SceneView& scene, uint64_t key, std::shared_ptr<const PathEnvironment> environment);
  bool settled(uint64_t key) const;
  // Batches that have landed since the last reset().
  uint64_t landed() const { return landed_; }

 private:
  struct Batch {
    std::vector<ProbeGrid> grids;
    std::shared_ptr<const PathScene> scene;
    uint64_t key = 0;
  };

  ProbeUpdateSettings settings_;
  uint32_t settle_sweeps_;
  std::vector<ProbeGrid> grids_;
  std::shared_ptr<const PathScene> scene_;  // what the last batch traced, and its key
  uint64_t scene_key_ = 0;
  uint64_t next_update_ = 0, landed_ = 0;
  uint64_t steady_batches_ = 0;  // landed in a row on scene_key_
  std::future<Batch> batch_;
};

}  // namespace lg
