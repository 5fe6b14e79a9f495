// The geometry bakes and ray-traced references work on: every draw of a SceneView moved into world space (positions,
// unit normals by the inverse transpose, indices into one shared vertex list, draws in order),
// with each draw's range of vertices, and a hash that identifies it across machines.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "runtime/scene/scene_view.h"

namespace lg {

struct WorldMesh {
  struct Part {
    std::string name;  // the mesh's name
    uint32_t first_vertex = 0, vertex_count = 0;
    uint32_t first_triangle = 0, triangle_count = 0;
  };
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // one per position; (0, 0, 0) where the transformed normal is degenerate
  std::vector<glm::vec2> uvs;      // one per position; (0, 0) where the mesh has none
  std::vector<glm::vec2> uvs1;     // texcoord set 1, the same way
  std::vector<glm::vec4> colors;   // one per position; (1, 1, 1, 1) where the mesh has none
  // One per position: xyz the tangent moved by the draw's matrix (as the G-buffer's vertex stage
  // moves it), w the bitangent's sign (flipped by a mirroring matrix); (0, 0, 0, 0) where the
  // mesh has none and its material no normal texture. A normal-mapped mesh without tangents gets
  // them from generate_tangents(), the importer's generator.
  std::vector<glm::vec4> tangents;
  std::vector<uint32_t> indices;  // three per triangle
  std::vector<Part> parts;        // one per draw

  size_t triangle_count() const { return indices.size() / 3; }
};

// Throws std::invalid_argument for a malformed mesh or a non-finite position, naming the mesh.
WorldMesh make_world_mesh(const SceneView& view);

// FNV-1a over the positions, normals and indices (bytes as stored; not the uvs, colours and
// tangents): equal for the same input read on any machine of the same float format.
uint64_t world_mesh_hash(const WorldMesh& mesh);

}  // namespace lg
