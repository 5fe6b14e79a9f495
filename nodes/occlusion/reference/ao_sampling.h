// What the camera-view ambient-occlusion references share: the settings (ray count, the
// maximum distance and GTAO's falloff ramp), the directions of a pixel's rays (the same ones
// whatever the geometry is traced against, so the full-scene and height-field references differ
// only by what they trace), and how hit distances fold into visibility k_A, a bent normal and
// its cone. The bakes' estimator (nodes/occlusion/estimate/occlusion_estimate.h) has its own
// obscurance curve; GTAO's linear ramp is what these references must match.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <vector>

namespace lg {

struct AoSettings {
  int rays = 512;  // per pixel, stratified
  // Hits farther than this do not occlude. GTAO's `radius` is passed here (XeGTAO's reference
  // does the same): the reference then answers the question GTAO's search radius asks.
  double max_distance = std::numeric_limits<double>::infinity();
  // A hit at distance t occludes fully up to falloff_from * max_distance and linearly less
  // beyond, to 0 at max_distance: the ramp GTAO applies to its horizon samples (62% to 100% of
  // the radius, nodes/occlusion/gtao/shaders/horizons.comp).
  double falloff_from = 0.62;
  uint64_t seed = 1;
};

// How much a hit at `distance` occludes, 0 to 1 (an infinite distance is no hit: 0).
double occlusion_weight(double distance, const AoSettings& settings);

// `settings.rays` cosine-distributed unit directions about unit `normal`, stratified
// (nodes/raytrace/cosine_sampling.h), jittered by the seed and `pixel` (y * width + x)
// alone: every reference gives a pixel the same directions about the same normal.
std::vector<glm::dvec3> cosine_directions(glm::dvec3 normal, const AoSettings& settings, uint64_t pixel);

// Accumulates one pixel's rays.
class OcclusionSum {
 public:
  void add(glm::dvec3 direction, double weight);  // weight: occlusion_weight of its hit, or 0
  // Visibility k_A (1 = open), the bent normal (mean unoccluded direction, normalised; the
  // normal when everything is occluded) and the cone cosine sqrt(1 - k_A), as GTAO writes it.
  glm::dvec4 bent_normal_and_cone(glm::dvec3 normal) const;
  double visibility() const;

 private:
  double visible_ = 0;
  int count_ = 0;
  glm::dvec3 bent_{0.0};
};

}  // namespace lg
