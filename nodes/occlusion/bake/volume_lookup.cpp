// The visibility grid's bake and its lookup in double (volume_lookup.h).
#include "nodes/occlusion/bake/volume_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "nodes/occlusion/bake/bake_run.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {

VisibilityGrid bake_visibility_grid(const RayScene& scene, const BakeDomain& volume, const OcclusionSettings& settings,
                                    uint64_t seed) {
  if (volume.mode() != BakeMode::volume) throw std::invalid_argument("a visibility grid needs a volume domain");
  check_occlusion_settings(settings);
  VisibilityGrid grid{volume.dims(), volume.origin(), volume.spacing(), {}};
  grid.points.resize(volume.size());
  const double surface_distance = volume_surface_cells * grid.spacing.x;
  parallel_for(grid.points.size(), [&](size_t i) {
    const SphereVisibility s =
        estimate_sphere_visibility(scene, volume.sample(i).point.position, settings, point_seed(seed, i));
    const bool invalid = s.backface_fraction > inside_backface_fraction || s.nearest_hit < surface_distance;
    grid.points[i] = invalid ? glm::vec4(0.0f, 0.0f, 0.0f, -1.0f) : glm::vec4(s.mean_direction, s.visibility);
  });
  return grid;
}

VolumeOcclusion lookup_volume_occlusion(const VisibilityGrid& grid, glm::dvec3 position, glm::dvec3 normal) {
  VolumeOcclusion open{1.0, normal, 0.0};
  if (grid.points.empty()) return open;
  const glm::dvec3 g = (position + normal * (volume_lookup_offset_cells * grid.spacing.x) - grid.origin) / grid.spacing;
  std::array<uint32_t, 3> lo{};
  glm::dvec3 f;
  for (int a = 0; a < 3; ++a) {
    const double c = std::clamp(g[a], 0.0, double(grid.dims[a] - 1));
    lo[a] = std::min(uint32_t(c), grid.dims[a] - 2);
    f[a] = c - lo[a];
  }
  double weight = 0.0, v = 0.0;
  glm::dvec3 m(0.0);
  for (uint32_t corner = 0; corner < 8; ++corner) {
    const uint32_t x = lo[0] + (corner & 1), y = lo[1] + ((corner >> 1) & 1), z = lo[2] + (corner >> 2);
    const glm::vec4& p = grid.points[(size_t(z) * grid.dims[1] + y) * grid.dims[0] + x];
    if (p.w < 0.0f) continue;  // inside geometry or on a surface
    const double w =
        ((corner & 1) ? f.x : 1.0 - f.x) * (((corner >> 1) & 1) ? f.y : 1.0 - f.y) * ((corner >> 2) ? f.z : 1.0 - f.z);
    weight += w, v += w * p.w, m += w * glm::dvec3(p);
  }
  if (weight < volume_lookup_min_weight) return open;
  v /= weight, m /= weight;
  const double mn = glm::dot(m, normal);
  const double ao = std::clamp(v + 2.0 * mn, 0.0, 1.0);
  const glm::dvec3 bent = (2.0 / 3.0) * v * normal + 0.75 * (m + mn * normal);
  const double length = glm::length(bent);
  return {ao, length > 1e-8 ? bent / length : normal, std::sqrt(1.0 - ao)};
}

}  // namespace lg
