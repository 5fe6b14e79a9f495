// Moving a ray's origin off the surface it starts on, so that the surface itself is not hit
// through floating-point error (self-intersection), by an amount that scales with the
// coordinates' magnitude rather than a fixed epsilon that is too small far from the origin and
// too large near it.
#pragma once

#include <glm/vec3.hpp>

namespace lg {

// `point` moved along `normal` (unit, the side rays leave toward) by a few hundred units in the
// last place of each coordinate, or by a small absolute amount (1/65536 of the normal) for
// coordinates near zero, where units in the last place are too fine. This is the integer-ulp
// offset of Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection"
// (Ray Tracing Gems, 2019).
glm::vec3 offset_ray_origin(glm::vec3 point, glm::vec3 normal);

}  // namespace lg
