#include "nodes/gi/probes/probe_projection.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "nodes/env/common/sh_basis.h"
#include "nodes/gi/probes/octahedral_map.h"

namespace lg {
namespace {

constexpr double kDistanceSharpness = 50;  // DDGI's cos^50 weighting of the distance moments

// The directions of the centres of a k x k octahedral map's texels, row by row.
template <int K>
std::array<glm::dvec3, K * K> texel_normals() {
  std::array<glm::dvec3, K * K> out;
  for (int t = 0; t < K * K; ++t) out[t] = octahedral_decode({(t % K + 0.5) / K, (t / K + 0.5) / K});
  return out;
}

}  // namespace

double probe_max_distance(const ProbeGrid& grid) {
  return 1.5 * glm::length(grid.axis(0) + grid.axis(1) + grid.axis(2));
}

ProbeProjection::ProbeProjection(uint32_t ray_count, double max_distance)
    : weight_(4.0 * std::numbers::pi / ray_count), max_distance_(max_distance) {}  // uniform over the sphere

void ProbeProjection::add(glm::dvec3 d, glm::dvec3 radiance, double distance) {
  static const auto irradiance_normals = texel_normals<kProbeIrradianceTexels>();
  static const auto distance_normals = texel_normals<kProbeDistanceTexels>();
  const glm::dvec3 l = std::isfinite(radiance.x + radiance.y + radiance.z) ? radiance : glm::dvec3(0.0);
  double basis[kProbeShCount];
  sh_evaluate(2, d, basis);
  for (int c = 0; c < kProbeShCount; ++c) sh_[c] += l * basis[c] * weight_;
  for (int a = 0; a < 3; ++a) {
    cube_[2 * a] += l * std::max(d[a], 0.0) * weight_;
    cube_[2 * a + 1] += l * std::max(-d[a], 0.0) * weight_;
  }
  for (int t = 0; t < kIrradianceTexels; ++t)
    irradiance_[t] += l * std::max(glm::dot(irradiance_normals[t], d), 0.0) * weight_;
  const double t_hit = std::min(distance, max_distance_);
  for (int t = 0; t < kDistanceTexels; ++t) {  // half the texels face away: no pow for them
    const double c = glm::dot(distance_normals[t], d);
    if (c > 0.0) moments_[t] += std::pow(c, kDistanceSharpness) * glm::dvec3(1.0, t_hit, t_hit * t_hit);
  }
}

void ProbeProjection::store(ProbeData& out) const {
  for (int c = 0; c < kProbeShCount; ++c) {
    const int band = c == 0 ? 0 : c < 4 ? 1 : 2;
    out.sh[c] = glm::vec3(sh_[c] * cosine_lobe_band(band));  // radiance to irradiance
  }
  for (int f = 0; f < 6; ++f) out.ambient_cube[f] = glm::vec3(cube_[f]);
  for (int t = 0; t < kIrradianceTexels; ++t) out.irradiance[t] = glm::vec3(irradiance_[t]);
  const glm::vec2 far(float(max_distance_), float(max_distance_ * max_distance_));
  for (int t = 0; t < kDistanceTexels; ++t)
    out.distance[t] =
        moments_[t].x > 0.0 ? glm::vec2(moments_[t].y / moments_[t].x, moments_[t].z / moments_[t].x) : far;
}

}  // namespace lg
