// The directions a probe traces along: a spherical Fibonacci set turned by a random rotation
// (DDGI turns its rays anew for each update). The bake and the dynamic update share them.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace lg {

// Direction `index` of `count` of a spherical Fibonacci set (even over the sphere, far more so
// than independent or jittered points: cosine lobes integrate to a fraction of a percent with
// 256), turned by `rotation`.
glm::dvec3 sphere_direction(uint32_t index, uint32_t count, const glm::dmat3& rotation);

// A uniformly random rotation drawn from `seed` (Shoemake's quaternion from three uniform numbers).
glm::dmat3 random_rotation(uint64_t seed);

}  // namespace lg
