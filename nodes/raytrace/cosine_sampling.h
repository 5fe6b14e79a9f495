// Stratified, deterministic cosine-weighted hemisphere sampling. Sample `index` of `count` lies
// in its own cell of an equal-area partition of the unit square (rows of jittered cells, any
// count), mapped to the disk by Shirley and Chiu's concentric map and lifted to the hemisphere
// (Malley's method), so each cell holds 1/count of the cosine-weighted solid angle. The jitter
// depends only on (seed, index): any split of the samples over threads or chunks gives the same
// directions.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lg {

// A well-mixed 64-bit hash (the splitmix64 finaliser).
uint64_t mix_bits(uint64_t x);
// A uniform number in [0, 1) from (seed, index, dimension).
double hashed_uniform(uint64_t seed, uint64_t index, uint32_t dimension);

// The point of sample `index` (< count) in [0, 1)^2: rows = floor(sqrt(count)), row r holding
// count / rows cells (the first count % rows rows one more), each row as tall as its share of
// the samples, so every cell has area 1/count; jittered uniformly inside its cell.
glm::dvec2 stratified_point(uint32_t index, uint32_t count, uint64_t seed);

// The concentric map of [0, 1)^2 onto the unit disk (area-preserving).
glm::dvec2 concentric_disk(glm::dvec2 u);
// A cosine-distributed direction about +Z from a point of [0, 1)^2 (z > 0 up to rounding).
glm::dvec3 cosine_hemisphere(glm::dvec2 u);

// An orthonormal frame with `normal` (unit) as its third axis.
struct Frame {
  glm::dvec3 tangent, bitangent, normal;
  glm::dvec3 to_world(glm::dvec3 local) const { return tangent * local.x + bitangent * local.y + normal * local.z; }
};
// Branch-free (Duff et al. 2017), continuous except across normal.z = 0.
Frame make_frame(glm::dvec3 normal);

}  // namespace lg
