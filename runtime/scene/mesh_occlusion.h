// Ambient occlusion baked offline for one mesh (`lumagraph bake --mode vertex|texel`, a .lgbake
// file named by a scene file's "occlusion" key; docs/scene-format.md), as the occlusion.baked node
// draws it: per vertex, or a lightmap with each triangle corner's place in it. Vertex values are
// in the mesh's own space, and the lightmap's turn into it by `lightmap_to_mesh`, so the bent
// normals turn with the draw's normal matrix. The scene library only
// carries this data; reading and checking .lgbake files belongs to the nodes
// (nodes/occlusion/baked/occlusion_bake_reader.h), handed to the loader as an OcclusionBakeReader.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace lg {

struct MeshData;

// A texel bake's lightmap, shared by every mesh of the bake: size x size texels, row-major from
// the top-left (UV (0, 0)); xyz the bent normal, w k_A; unused texels are 0.
struct OcclusionLightmap {
  uint32_t size = 0;
  std::vector<glm::vec4> texels;
};

struct MeshOcclusion {
  enum class Kind { vertex, texel };
  Kind kind = Kind::vertex;
  std::string source;  // the .lgbake file
  // vertex: one per mesh vertex, xyz the unit bent normal, w k_A in [0, 1].
  std::vector<glm::vec4> vertices;
  // texel: the lightmap, and this mesh's triangle corners in it (3 per triangle, mesh order);
  // the lightmap's bent normals are in the bake's space, which this takes to the mesh's
  // (identity for a bake of the model alone; for a bake of a whole scene the transpose of the
  // draw's 3x3 world matrix, the inverse of its normal matrix).
  std::shared_ptr<const OcclusionLightmap> lightmap;
  std::vector<glm::vec2> lightmap_uvs;
  glm::mat3 lightmap_to_mesh{1.0f};
};

// Reads the bake at `bake_path` for `meshes` drawn with the world matrices `transforms`, in draw
// order, as the bake must have traced them: one scene-file entity's meshes with identity
// transforms (a bake of its model alone), or every draw of a scene file where they stand (a bake
// of the scene file). One MeshOcclusion each, in mesh space. Throws std::runtime_error with a
// sentence that says why the bake cannot be used (unreadable, a volume bake, or made from other
// geometry).
using OcclusionBakeReader = std::function<std::vector<std::shared_ptr<const MeshOcclusion>>(
    const std::string& bake_path, std::span<const MeshData* const> meshes, std::span<const glm::mat4> transforms)>;

}  // namespace lg
