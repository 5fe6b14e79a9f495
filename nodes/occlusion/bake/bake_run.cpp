// run_bake(): each point of the range traced by estimate_occlusion (surfaces) or
// estimate_sphere_visibility (volume points), batches of points spread over all cores.
#include "nodes/occlusion/bake/bake_run.h"

#include "nodes/raytrace/parallel_for.h"

namespace lg {

BakeData run_bake(const RayScene& scene, const BakeDomain& domain, const OcclusionSettings& settings, uint64_t seed,
                  PointRange range, const std::function<void(uint64_t)>& progress) {
  check_occlusion_settings(settings);
  BakeData data;
  data.resize(range.size());
  auto bake_point = [&](size_t j) {
    const uint64_t index = range.begin + j;
    const BakeSample sample = domain.sample(index);
    if (sample.coverage == 0.0f) return;  // zeros
    float visibility;
    glm::vec3 bent;
    if (sample.sphere) {
      const SphereVisibility v =
          estimate_sphere_visibility(scene, sample.point.position, settings, point_seed(seed, index));
      if (v.backface_fraction > inside_backface_fraction) return;  // inside geometry: zeros
      visibility = v.visibility, bent = v.bent_normal;
    } else {
      const OcclusionResult r =
          estimate_occlusion(scene, sample.point.position, sample.point.normal, settings, point_seed(seed, index));
      visibility = r.visibility, bent = r.bent_normal;
    }
    data.visibility[j] = visibility;
    data.bent_normal[3 * j] = bent.x, data.bent_normal[3 * j + 1] = bent.y, data.bent_normal[3 * j + 2] = bent.z;
    data.valid[j] = sample.coverage;
  };
  parallel_for_with_progress(range.size(), bake_point, progress);
  return data;
}

}  // namespace lg
