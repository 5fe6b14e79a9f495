// Ambient occlusion baked offline for one mesh (`lumagraph bake --mode vertex|texel`, a .lgbake
// file named by a scene file's "occlusion" key; docs/scene-format.md), as the occlusion.baked node
// draws it: per vertex, or a lightmap with each triangle corner's place in it. Values are in the
// mesh's own space: the bent normals turn with the draw's normal matrix. The scene library only
// carries this data; reading and checking .lgbake files belongs to the nodes
// (nodes/occlusion/baked/occlusion_bake_reader.h), handed to the loader as an OcclusionBakeReader.
#pragma once

#include <cstdint>
#include <functional>
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
  // texel: the lightmap, and this mesh's triangle corners in it (3 per triangle, mesh order).
  std::shared_ptr<const OcclusionLightmap> lightmap;
  std::vector<glm::vec2> lightmap_uvs;
};

// Reads the bake at `bake_path` for `meshes`, the meshes one scene-file entity draws, in draw
// order: one MeshOcclusion each. Throws std::runtime_error with a sentence that says why the bake
// cannot be used (unreadable, a volume bake, or made from other geometry).
using OcclusionBakeReader = std::function<std::vector<std::shared_ptr<const MeshOcclusion>>(
    const std::string& bake_path, std::span<const MeshData* const> meshes)>;

}  // namespace lg
