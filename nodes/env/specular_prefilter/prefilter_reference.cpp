#include "nodes/env/specular_prefilter/prefilter_reference.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {

glm::dvec3 prefiltered_reference(const CubeImage& env, const glm::dvec3& n, double roughness) {
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  glm::dvec3 sum(0.0);
  double weight = 0;
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < env.size; ++j)
      for (uint32_t i = 0; i < env.size; ++i) {
        const glm::dvec3 l = env.direction(f, i, j);
        const double n_dot_l = glm::dot(n, l);
        if (n_dot_l <= 0) continue;
        const double n_dot_h = glm::dot(n, glm::normalize(n + l));
        const double d = n_dot_h * n_dot_h * (a2 - 1) + 1;
        const double w = a2 / (std::numbers::pi * d * d) * n_dot_l * texel_solid_angle(env.size, i, j);
        const glm::dvec3 radiance(env.at(f, i, j));
        if (std::isfinite(radiance.x) && std::isfinite(radiance.y) && std::isfinite(radiance.z)) sum += w * radiance;
        weight += w;
      }
  return sum / weight;
}

}  // namespace lg
