// occlusion.bake's per-frame volume path on the CPU, in double: the visibility grid it bakes
// (per point the L1 spherical-harmonic projection of visibility over the sphere, V(w) ~ v +
// 3 m . w, with v the mean visibility and m the unnormalised mean unoccluded direction) and the
// lookup that shaders/volume_lookup.comp runs per pixel in float, so tests compare the two.
//
// The lookup at a surface point p with unit normal n samples the grid trilinearly at p + n *
// (0.75 cell), weighting only valid points (points inside geometry or on a surface weigh 0; none valid: ao
// 1, bent normal n). With the L1 visibility the cosine-weighted visibility about n is exactly
// k_A = clamp(v + 2 m . n, 0, 1) (an open plane: v = 1/2, m . n = 1/4, so 1; a closed box: 0),
// and the cosine-weighted mean unoccluded direction is proportional to (2/3) v n + (3/4) (m +
// (m . n) n), normalised for the bent normal (n when it vanishes). The cone cosine is
// sqrt(1 - k_A), occlusion.gtao's convention.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "nodes/occlusion/bake/bake_domain.h"
#include "nodes/occlusion/estimate/occlusion_estimate.h"
#include "nodes/raytrace/ray_scene.h"

namespace lg {

// Where the grid's lookup samples, in cells along the normal (off the surface it shades).
inline constexpr double volume_lookup_offset_cells = 0.75;
// A grid point closer than this many cells to its nearest hit sits on a surface: the surface
// cuts through its rays' origin, so its visibility says nothing of either side (a lone floor
// through a layer of points gives v = 0 there); like a point inside geometry it weighs 0.
inline constexpr double volume_surface_cells = 1e-3;
// Below this total trilinear weight of valid points a lookup has no data (ao 1, bent n).
inline constexpr double volume_lookup_min_weight = 1e-4;

struct VisibilityGrid {
  std::array<uint32_t, 3> dims{0, 0, 0};  // all 0: no geometry, every lookup is open
  glm::dvec3 origin{0.0}, spacing{0.0};   // cubic cells: spacing.x == y == z
  // vec4(m, v) per point in BakeDomain's volume order (x fastest); w = -1 inside geometry or on
  // a surface.
  std::vector<glm::vec4> points;
};

// Bakes the volume domain's points on all cores (point i seeded with point_seed(seed, i), so
// the grid is the same on every run); a point whose rays mostly hit back faces is inside, one
// within volume_surface_cells of a hit is on a surface.
VisibilityGrid bake_visibility_grid(const RayScene& scene, const BakeDomain& volume, const OcclusionSettings& settings,
                                    uint64_t seed);

struct VolumeOcclusion {
  double ao = 1.0;              // k_A
  glm::dvec3 bent_normal{0.0};  // unit
  double cone_cos = 0.0;        // sqrt(1 - k_A)
};

VolumeOcclusion lookup_volume_occlusion(const VisibilityGrid& grid, glm::dvec3 position, glm::dvec3 normal);

}  // namespace lg
