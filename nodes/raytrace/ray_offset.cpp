// offset_ray_origin(): step each coordinate by whole units in the last place, away from the
// surface, so that the step is relative to the coordinate's own precision.
#include "nodes/raytrace/ray_offset.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace lg {
namespace {

constexpr float near_zero = 1.0f / 32.0f;         // below this, ulps are too fine to help
constexpr float absolute_step = 1.0f / 65536.0f;  // step for coordinates near zero
constexpr float ulps_per_unit_normal = 256.0f;    // step in ulps along a unit normal component

float offset_coordinate(float p, float n) {
  if (std::fabs(p) < near_zero) return p + absolute_step * n;
  // Moving the bit pattern of a positive float up makes it larger, of a negative one more negative.
  const int32_t ulps = int32_t(ulps_per_unit_normal * n);
  const int32_t bits = std::bit_cast<int32_t>(p);
  return std::bit_cast<float>(bits + (p < 0.0f ? -ulps : ulps));
}

}  // namespace

glm::vec3 offset_ray_origin(glm::vec3 point, glm::vec3 normal) {
  return {offset_coordinate(point.x, normal.x), offset_coordinate(point.y, normal.y),
          offset_coordinate(point.z, normal.z)};
}

}  // namespace lg
