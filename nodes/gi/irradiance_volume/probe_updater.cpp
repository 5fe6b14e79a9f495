#include "nodes/gi/irradiance_volume/probe_updater.h"

#include <algorithm>
#include <chrono>

namespace lg {

ProbeUpdater::~ProbeUpdater() {
  if (batch_.valid()) batch_.wait();
}

void ProbeUpdater::reset(std::vector<ProbeGrid> grids) {
  if (batch_.valid()) batch_.wait();
  batch_ = {};
  grids_ = std::move(grids);
  next_update_ = landed_ = steady_batches_ = 0;
}

const std::vector<ProbeGrid>* ProbeUpdater::finished() {
  if (!batch_.valid() || batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return nullptr;
  Batch done = batch_.get();  // leaves batch_ empty, also when it throws
  grids_ = std::move(done.grids);
  steady_batches_ = done.key == scene_key_ && landed_ > 0 ? steady_batches_ + 1 : 1;
  scene_ = std::move(done.scene);
  scene_key_ = done.key;
  ++landed_;
  return &grids_;
}

bool ProbeUpdater::settled(uint64_t key) const {
  if (settle_sweeps_ == 0 || key != scene_key_ || landed_ == 0) return false;
  size_t probes = 0;
  for (const ProbeGrid& g : grids_) probes += g.probes.size();
  const uint64_t per_sweep = (probes + settings_.probes_per_update - 1) / std::max(settings_.probes_per_update, 1u);
  return steady_batches_ >= uint64_t(settle_sweeps_) * std::max<uint64_t>(per_sweep, 1);
}

void ProbeUpdater::start(const SceneView& scene, uint64_t key, std::shared_ptr<const PathEnvironment> environment) {
  if (batch_.valid() || grids_.empty() || settled(key)) return;
  std::shared_ptr<const PathScene> traced = key == scene_key_ ? scene_ : nullptr;
  batch_ = std::async(std::launch::async,
                      [settings = settings_, update = next_update_++, grids = grids_, traced = std::move(traced),
                       view = scene, key, environment = std::move(environment)]() mutable {
                        if (!traced) traced = std::make_shared<const PathScene>(std::move(view), *environment);
                        update_probes(*traced, grids, settings, update);
                        return Batch{std::move(grids), std::move(traced), key};
                      });
}

}  // namespace lg
