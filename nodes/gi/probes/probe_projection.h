// Projecting what arrives at a probe along its rays into every form ProbeData holds (SH L2,
// ambient cube, octahedral irradiance, cos^50-weighted distance moments), shared by the bake and
// the dynamic update: add() each ray, then store() the sums into a probe.
#pragma once

#include <array>
#include <glm/vec3.hpp>

#include "nodes/gi/probes/probe_grid.h"

namespace lg {

// How far a ray that escapes counts for the distance moments (DDGI clamps to its ray length):
// 1.5 cell diagonals.
double probe_max_distance(const ProbeGrid& grid);

class ProbeProjection {
 public:
  // `ray_count` rays spread evenly over the sphere; escaping rays count as `max_distance`.
  ProbeProjection(uint32_t ray_count, double max_distance);

  // Radiance `radiance` arriving along unit direction d from a surface `distance` away
  // (infinite on a miss); a non-finite radiance counts as 0.
  void add(glm::dvec3 d, glm::dvec3 radiance, double distance);
  // The irradiance forms and distance moments into `out` (its placement left as it is).
  void store(ProbeData& out) const;

 private:
  static constexpr int kIrradianceTexels = kProbeIrradianceTexels * kProbeIrradianceTexels;
  static constexpr int kDistanceTexels = kProbeDistanceTexels * kProbeDistanceTexels;
  double weight_, max_distance_;
  std::array<glm::dvec3, kProbeShCount> sh_{};
  std::array<glm::dvec3, 6> cube_{};
  std::array<glm::dvec3, kIrradianceTexels> irradiance_{};
  std::array<glm::dvec3, kDistanceTexels> moments_{};  // sum of w, w t, w t^2
};

}  // namespace lg
