// baked_occlusion_at(): the double-precision mirror of shaders/baked_raster.frag.
#include "nodes/occlusion/baked/baked_reference.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace lg {
namespace {

glm::dvec4 lightmap_bilinear(const OcclusionLightmap& map, glm::dvec2 uv) {
  const int size = int(map.size);
  const double x = uv.x * size - 0.5, y = uv.y * size - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto texel = [&](int i, int j) {
    return glm::dvec4(map.texels[size_t(std::clamp(j, 0, size - 1)) * size + size_t(std::clamp(i, 0, size - 1))]);
  };
  return (texel(x0, y0) * (1 - fx) + texel(x0 + 1, y0) * fx) * (1 - fy) +
         (texel(x0, y0 + 1) * (1 - fx) + texel(x0 + 1, y0 + 1) * fx) * fy;
}

}  // namespace

BakedSample baked_occlusion_at(const MeshData& mesh, const glm::dmat4& world, uint32_t triangle,
                               glm::dvec3 barycentric) {
  const MeshOcclusion& occlusion = *mesh.occlusion;
  glm::dvec4 value(0.0);  // bent normal (mesh space), k_A
  if (occlusion.kind == MeshOcclusion::Kind::vertex) {
    for (int c = 0; c < 3; ++c)
      value += barycentric[c] * glm::dvec4(occlusion.vertices[mesh.indices[3 * triangle + c]]);
  } else {
    glm::dvec2 uv(0.0);
    for (int c = 0; c < 3; ++c) uv += barycentric[c] * glm::dvec2(occlusion.lightmap_uvs[3 * triangle + c]);
    value = lightmap_bilinear(*occlusion.lightmap, uv);
    value = glm::dvec4(glm::dmat3(occlusion.lightmap_to_mesh) * glm::dvec3(value), value.w);
  }
  BakedSample s;
  s.ao = std::clamp(value.w, 0.0, 1.0);
  s.bent_normal = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(world))) * glm::dvec3(value));
  s.cone_cos = std::sqrt(1.0 - s.ao);
  return s;
}

glm::dvec3 barycentric_of(glm::dvec3 point, const std::array<glm::dvec3, 3>& corners) {
  const glm::dvec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], d = point - corners[0];
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double p1 = glm::dot(d, e1), p2 = glm::dot(d, e2);
  const double det = d11 * d22 - d12 * d12;
  const double b1 = (d22 * p1 - d12 * p2) / det, b2 = (d11 * p2 - d12 * p1) / det;
  return {1.0 - b1 - b2, b1, b2};
}

}  // namespace lg
