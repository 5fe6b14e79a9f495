#include "nodes/gi/probes/probe_directions.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

#include "nodes/raytrace/cosine_sampling.h"

namespace lg {

glm::dvec3 sphere_direction(uint32_t index, uint32_t count, const glm::dmat3& rotation) {
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  const double z = 1.0 - (2.0 * index + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double turns = index / golden;
  const double phi = 2.0 * std::numbers::pi * (turns - std::floor(turns));
  return rotation * glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
}

glm::dmat3 random_rotation(uint64_t seed) {
  constexpr double kPi = std::numbers::pi;
  const double u1 = hashed_uniform(seed, 0, 0), u2 = hashed_uniform(seed, 0, 1), u3 = hashed_uniform(seed, 0, 2);
  const glm::dquat q(std::sqrt(u1) * std::cos(2.0 * kPi * u3), std::sqrt(1.0 - u1) * std::sin(2.0 * kPi * u2),
                     std::sqrt(1.0 - u1) * std::cos(2.0 * kPi * u2), std::sqrt(u1) * std::sin(2.0 * kPi * u3));
  return glm::mat3_cast(q);
}

}  // namespace lg
