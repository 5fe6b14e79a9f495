// Runs a bake over a range of a BakeDomain's points on all cores: ambient visibility, bent
// normal and a validity value per point. Point i is seeded with point_seed(seed, i) whatever the
// range, so the results of a range are bit-identical to the same points of a whole run.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "nodes/occlusion/bake/bake_domain.h"
#include "nodes/occlusion/estimate/occlusion_estimate.h"
#include "nodes/raytrace/bake_chunks.h"
#include "nodes/raytrace/ray_scene.h"

namespace lg {

// A volume point whose rays mostly (over half) first hit back faces is inside geometry.
inline constexpr float inside_backface_fraction = 0.5f;

struct BakeData {
  std::vector<float> visibility;   // k_A per point, in [0, 1]; 0 where valid is 0
  std::vector<float> bent_normal;  // 3 per point, unit; (0, 0, 0) where valid is 0
  // 1: baked. 0: nothing to bake (unused texel, vertex without a normal) or, in a volume, a
  // point inside geometry. 0.5: texel padding around a chart (holds its nearest chart point).
  std::vector<float> valid;

  void resize(size_t points) { visibility.resize(points), bent_normal.resize(3 * points), valid.resize(points); }
  size_t size() const { return visibility.size(); }
};

// `progress` is called from the calling thread with the number of points done in the range.
BakeData run_bake(const RayScene& scene, const BakeDomain& domain, const OcclusionSettings& settings, uint64_t seed,
                  PointRange range, const std::function<void(uint64_t done)>& progress = {});

}  // namespace lg
