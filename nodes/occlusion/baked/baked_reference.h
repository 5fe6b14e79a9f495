// occlusion.baked in double precision, for tests: what the node writes at a surface point of a
// draw whose mesh carries baked occlusion. Vertex bakes interpolate k_A and the bent normal
// (turned by the draw's normal matrix, then normalised) with the point's barycentrics; texel
// bakes interpolate the corners' lightmap UVs and sample the lightmap bilinearly (texel centres
// at (i + 0.5) / size, indices clamped to the edge), the bent normal taken to mesh space by
// lightmap_to_mesh, then likewise. The cone cosine is sqrt(1 - k_A), GTAO's.
#pragma once

#include <array>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

struct BakedSample {
  double ao = 1.0;
  glm::dvec3 bent_normal{0.0};  // world space, unit
  double cone_cos = 0.0;
};

// `mesh.occlusion` must be set; `barycentric` weighs the corners of triangle `triangle`.
BakedSample baked_occlusion_at(const MeshData& mesh, const glm::dmat4& world, uint32_t triangle,
                               glm::dvec3 barycentric);

// The barycentric coordinates of `point` (on or near the triangle's plane) in `corners`.
glm::dvec3 barycentric_of(glm::dvec3 point, const std::array<glm::dvec3, 3>& corners);

}  // namespace lg
