#include "runtime/scene/mesh_plane.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "runtime/scene/mesh_tools.h"

namespace lg {

std::optional<MeshPlane> mesh_plane(const MeshData& mesh) {
  // Double precision: a 100 m floor's vertices still resolve 1e-6 of its size.
  glm::dvec3 area_normal(0.0), centroid(0.0);
  double area = 0.0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    const glm::dvec3 twice = glm::cross(b - a, c - a);
    const double triangle_area = 0.5 * glm::length(twice);
    area_normal += 0.5 * twice;
    centroid += triangle_area * (a + b + c) / 3.0;
    area += triangle_area;
  }
  const double normal_length = glm::length(area_normal);
  // Triangles facing both ways cancel: less than half their area left facing one way.
  if (!(area > 0.0) || !(normal_length > 0.5 * area)) return std::nullopt;
  const glm::dvec3 n = area_normal / normal_length;
  const double w = -glm::dot(n, centroid / area);
  Bounds bounds;
  double max_distance = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    bounds.add(p);
    max_distance = std::max(max_distance, std::abs(glm::dot(n, glm::dvec3(p)) + w));
  }
  const double size = glm::length(glm::dvec3(bounds.max - bounds.min));
  return MeshPlane{glm::vec4(glm::vec3(n), float(w)), max_distance, std::max(1e-4 * size, 1e-6)};
}

glm::vec4 transform_plane(const glm::vec4& plane, const glm::mat4& transform) {
  // Planes transform by the inverse transpose; renormalised so that w stays a distance.
  const glm::vec4 p = glm::transpose(glm::inverse(transform)) * plane;
  return p / glm::length(glm::vec3(p));
}

}  // namespace lg
