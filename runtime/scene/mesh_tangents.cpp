// generate_tangents(): see mesh_tangents.h.
#include "runtime/scene/mesh_tangents.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lg {
namespace {

// A unit vector perpendicular to the unit vector n.
glm::vec3 any_perpendicular(glm::vec3 n) {
  glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

float corner_angle(glm::vec3 a, glm::vec3 b) {
  float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f) || !(lb > 0.0f)) return 0.0f;
  return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
}

}  // namespace

void generate_tangents(MeshData& mesh, int uv_set) {
  const std::vector<glm::vec2>& uvs = uv_set == 1 ? mesh.uvs1 : mesh.uvs;
  const size_t count = mesh.positions.size();
  std::vector<glm::vec3> tangent(count, glm::vec3(0.0f)), bitangent(count, glm::vec3(0.0f));
  if (uvs.size() == count) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
      const glm::vec3 e1 = mesh.positions[v[1]] - mesh.positions[v[0]],
                      e2 = mesh.positions[v[2]] - mesh.positions[v[0]];
      const glm::vec2 d1 = uvs[v[1]] - uvs[v[0]], d2 = uvs[v[2]] - uvs[v[0]];
      const float det = d1.x * d2.y - d2.x * d1.y;
      if (!(std::abs(det) > 1e-20f)) continue;  // the uvs do not span the triangle
      // dP/du and -dP/dv: glTF's v grows downward, the normal map's +Y points up.
      glm::vec3 tu = (e1 * d2.y - e2 * d1.y) / det, tv = -(e2 * d1.x - e1 * d2.x) / det;
      if (!(glm::length(tu) > 0.0f) || !(glm::length(tv) > 0.0f) || !std::isfinite(glm::length(tu) + glm::length(tv)))
        continue;
      tu = glm::normalize(tu);
      tv = glm::normalize(tv);
      for (int c = 0; c < 3; ++c) {
        const glm::vec3 p = mesh.positions[v[c]];
        const float angle = corner_angle(mesh.positions[v[(c + 1) % 3]] - p, mesh.positions[v[(c + 2) % 3]] - p);
        tangent[v[c]] += angle * tu;
        bitangent[v[c]] += angle * tv;
      }
    }
  }
  mesh.tangents.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
    // Gram-Schmidt: the part of the accumulated tangent along the normal is removed.
    glm::vec3 t = tangent[i] - n * glm::dot(n, tangent[i]);
    const float length = glm::length(t);
    if (!(length > 1e-6f) || !std::isfinite(length)) {
      mesh.tangents[i] = glm::vec4(any_perpendicular(n), 1.0f);
      continue;
    }
    t /= length;
    mesh.tangents[i] = glm::vec4(t, glm::dot(glm::cross(n, t), bitangent[i]) < 0.0f ? -1.0f : 1.0f);
  }
}

}  // namespace lg
