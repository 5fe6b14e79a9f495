#include "nodes/raytrace/surface_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lg {

SurfaceLookup::SurfaceLookup(WorldMesh mesh) : mesh_(std::move(mesh)) {}

SurfaceAttributes SurfaceLookup::at(uint32_t primitive, glm::dvec3 point) const {
  const uint32_t* corner = &mesh_.indices[3 * size_t(primitive)];
  const glm::dvec3 a(mesh_.positions[corner[0]]), b(mesh_.positions[corner[1]]), c(mesh_.positions[corner[2]]);
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area2 = glm::dot(n, n);
  // Parts are in triangle order: the last whose first triangle is not past this one.
  const auto part = std::upper_bound(mesh_.parts.begin(), mesh_.parts.end(), primitive,
                                     [](uint32_t t, const WorldMesh::Part& p) { return t < p.first_triangle; });
  SurfaceAttributes out;
  out.draw = uint32_t(part - mesh_.parts.begin()) - 1;
  if (!(area2 > 0.0)) {  // never hit: zero area
    out.normal = glm::dvec3(0.0, 0.0, 1.0);
    out.texcoords = {glm::dvec2(mesh_.uvs[corner[0]]), glm::dvec2(mesh_.uvs1[corner[0]]),
                     glm::dvec4(mesh_.colors[corner[0]])};
    return out;
  }
  const double wb = glm::dot(glm::cross(point - a, c - a), n) / area2;
  const double wc = glm::dot(glm::cross(b - a, point - a), n) / area2;
  const double wa = 1.0 - wb - wc;
  const glm::dvec3 interpolated = wa * glm::dvec3(mesh_.normals[corner[0]]) +
                                  wb * glm::dvec3(mesh_.normals[corner[1]]) + wc * glm::dvec3(mesh_.normals[corner[2]]);
  const double length = glm::length(interpolated);
  out.normal = length > 1e-12 ? interpolated / length : n / std::sqrt(area2);
  auto interpolate = [&]<class T>(const std::vector<T>& values) {
    using D = glm::vec<T::length(), double>;
    return wa * D(values[corner[0]]) + wb * D(values[corner[1]]) + wc * D(values[corner[2]]);
  };
  out.texcoords = {interpolate(mesh_.uvs), interpolate(mesh_.uvs1), interpolate(mesh_.colors)};
  out.tangent = glm::dvec4(glm::dvec3(interpolate(mesh_.tangents)), mesh_.tangents[corner[0]].w);
  return out;
}

}  // namespace lg
