// Helpers shared by the mesh importers and generators: normals from triangles, bounds, checks.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "runtime/scene/scene_view.h"

namespace lg {

// Area-weighted vertex normals from the triangles (counter-clockwise front faces); a vertex
// touching only degenerate triangles gets +Y.
void generate_normals(MeshData& mesh);

struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void add(glm::vec3 p);
  glm::vec3 center() const { return (min + max) * 0.5f; }
};

// The box around the mesh's positions after `transform`.
Bounds transformed_bounds(const MeshData& mesh, const glm::mat4& transform);

// What is wrong with the mesh (index out of range, count not a multiple of 3, normals, uvs,
// colours or tangents not one per position, non-finite position), or empty when it is well formed.
std::string mesh_problem(const MeshData& mesh);

}  // namespace lg
