// make_world_mesh(): the SceneView's draws flattened into one world-space vertex list.
#include "nodes/raytrace/world_mesh.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "graph/fnv1a.h"
#include "runtime/scene/mesh_tangents.h"
#include "runtime/scene/mesh_tools.h"

namespace lg {
namespace {

// The mesh's tangents, or those generate_tangents() gives it when its material has a normal
// texture and the file brought none; empty otherwise.
std::vector<glm::vec4> draw_tangents(const MeshData& mesh, const PbrMaterial& material) {
  if (!mesh.tangents.empty() || material.normal_texture.texture < 0) return mesh.tangents;
  MeshData copy = mesh;
  generate_tangents(copy, material.normal_texture.texcoord);
  return std::move(copy.tangents);
}

}  // namespace

WorldMesh make_world_mesh(const SceneView& view) {
  WorldMesh out;
  for (size_t d = 0; d < view.draws.size(); ++d) {
    const DrawItem& draw = view.draws[d];
    const MeshData& mesh = view.mesh_of(draw);
    if (std::string problem = mesh_problem(mesh); !problem.empty())
      throw std::invalid_argument("mesh '" + mesh.name + "': " + problem);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(draw.world)));
    const std::vector<glm::vec4> tangents = draw_tangents(mesh, view.material_of(draw));
    const float handedness = glm::determinant(glm::mat3(draw.world)) < 0.0f ? -1.0f : 1.0f;
    const uint32_t base = uint32_t(out.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3 p = glm::vec3(draw.world * glm::vec4(mesh.positions[v], 1.0f));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw std::invalid_argument("mesh '" + mesh.name + "': vertex " + std::to_string(v) +
                                    " has a non-finite world position; positions must be finite numbers");
      out.positions.push_back(p);
      const glm::vec3 n = normal_matrix * mesh.normals[v];
      const float length = glm::length(n);
      out.normals.push_back(std::isfinite(length) && length > 1e-20f ? n / length : glm::vec3(0.0f));
      out.uvs.push_back(mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[v]);
      out.uvs1.push_back(mesh.uvs1.empty() ? glm::vec2(0.0f) : mesh.uvs1[v]);
      out.colors.push_back(mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[v]);
      out.tangents.push_back(
          tangents.empty() ? glm::vec4(0.0f)
                           : glm::vec4(glm::mat3(draw.world) * glm::vec3(tangents[v]), handedness * tangents[v].w));
    }
    const uint32_t first_triangle = uint32_t(out.triangle_count());
    for (uint32_t i : mesh.indices) out.indices.push_back(base + i);
    out.parts.push_back(
        {mesh.name, base, uint32_t(mesh.positions.size()), first_triangle, uint32_t(mesh.indices.size() / 3)});
  }
  return out;
}

uint64_t world_mesh_hash(const WorldMesh& mesh) {
  uint64_t hash = fnv1a_basis;
  auto add = [&](const void* data, size_t bytes) { hash = fnv1a(data, bytes, hash); };
  add(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
  add(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
  add(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  return hash;
}

}  // namespace lg
