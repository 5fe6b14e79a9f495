#include "nodes/env/irradiance/irradiance_reference.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {

glm::dvec3 irradiance_over_pi_reference(const CubeImage& env, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < env.size; ++j)
      for (uint32_t i = 0; i < env.size; ++i) {
        const double n_dot_l = glm::dot(n, env.direction(f, i, j));
        const glm::dvec3 radiance(env.at(f, i, j));
        if (n_dot_l <= 0 || !std::isfinite(radiance.x) || !std::isfinite(radiance.y) || !std::isfinite(radiance.z))
          continue;
        sum += radiance * n_dot_l * texel_solid_angle(env.size, i, j);
      }
  return sum / std::numbers::pi;
}

}  // namespace lg
