#include "nodes/gi/irradiance_volume/probe_updater.h"

#include <chrono>

namespace lg {

ProbeUpdater::~ProbeUpdater() {
  if (batch_.valid()) batch_.wait();
}

void ProbeUpdater::reset(std::vector<ProbeGrid> grids) {
  if (batch_.valid()) batch_.wait();
  batch_ = {};
  grids_ = std::move(grids);
  next_update_ = landed_ = 0;
}

const std::vector<ProbeGrid>* ProbeUpdater::finished() {
  if (!batch_.valid() || batch_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return nullptr;
  Batch done = batch_.get();  // leaves batch_ empty, also when it throws
  grids_ = std::move(done.grids);
  scene_ = std::move(done.scene);
  scene_key_ = done.key;
  ++landed_;
  return &grids_;
}

void ProbeUpdater::start(const SceneView& scene, uint64_t key, std::shared_ptr<const PathEnvironment> environment) {
  if (batch_.valid() || grids_.empty()) return;
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
