#include "runtime/scene/mesh_tools.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace lg {

void generate_normals(MeshData& mesh) {
  std::vector<glm::vec3> sums(mesh.positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // The cross product's length is twice the area: larger triangles weigh more.
    glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    sums[a] += n;
    sums[b] += n;
    sums[c] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (size_t i = 0; i < sums.size(); ++i) {
    float length = glm::length(sums[i]);
    mesh.normals[i] = length > 0.0f && std::isfinite(length) ? sums[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void Bounds::add(glm::vec3 p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Bounds transformed_bounds(const MeshData& mesh, const glm::mat4& transform) {
  Bounds b;
  for (const auto& p : mesh.positions) b.add(glm::vec3(transform * glm::vec4(p, 1.0f)));
  return b;
}

std::string mesh_problem(const MeshData& mesh) {
  if (mesh.indices.size() % 3 != 0) return std::to_string(mesh.indices.size()) + " indices, not a multiple of 3";
  for (uint32_t i : mesh.indices)
    if (i >= mesh.positions.size())
      return "index " + std::to_string(i) + " is out of range (" + std::to_string(mesh.positions.size()) + " vertices)";
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) return "normals are not one per vertex";
  auto per_vertex = [&](const auto& v) { return v.empty() || v.size() == mesh.positions.size(); };
  if (!per_vertex(mesh.uvs)) return "uvs are not one per vertex";
  if (!per_vertex(mesh.uvs1)) return "uvs of set 1 are not one per vertex";
  if (!per_vertex(mesh.colors)) return "colours are not one per vertex";
  if (!per_vertex(mesh.tangents)) return "tangents are not one per vertex";
  for (const auto& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "a vertex position is not finite";
  return {};
}

}  // namespace lg
