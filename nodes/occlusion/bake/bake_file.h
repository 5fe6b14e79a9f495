// The .lgbake file: one bake's results, whole or one chunk of them, in the layout of
// docs/bake-format.md: the magic "LGBAKE01", the header's length (uint64, little-endian), the
// header (JSON: what was baked, from which input, with which settings, which chunk, where each
// array lies), zero padding to a multiple of 16 bytes, then the arrays as little-endian float32.
// merge_bake_parts() checks that parts belong to the same bake and cover it exactly once.
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "nodes/occlusion/bake/bake_domain.h"
#include "nodes/occlusion/bake/bake_run.h"
#include "nodes/occlusion/estimate/occlusion_estimate.h"
#include "nodes/raytrace/bake_container.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

struct BakeHeader {
  BakeMode mode = BakeMode::vertex;
  std::string input;        // the mesh or scene file as named on the command line
  uint64_t input_hash = 0;  // world_mesh_hash() of its geometry
  OcclusionSettings occlusion;
  uint64_t seed = 1;
  uint64_t points = 0;  // in the whole bake
  uint32_t chunk_index = 0, chunk_count = 1;
  PointRange range;  // the points this file holds
  // vertex: each draw's vertices
  std::vector<WorldMesh::Part> parts;
  // texel
  uint32_t lightmap_size = 0;
  uint64_t triangles = 0;
  // volume
  std::array<uint32_t, 3> dims{0, 0, 0};
  glm::dvec3 origin{0.0}, spacing{0.0};
};

struct BakeFile {
  BakeHeader header;
  BakeData data;                    // header.range.size() points
  std::vector<float> lightmap_uvs;  // texel: 6 per triangle (BakeDomain::lightmap_uvs)
};

// The header a bake of `domain` writes for `range` (chunk `index` of `count`).
BakeHeader make_bake_header(const BakeDomain& domain, const WorldMesh& mesh, const std::string& input,
                            const OcclusionSettings& occlusion, uint64_t seed, uint32_t index, uint32_t count);

std::string encode_bake_file(const BakeFile& file);
// Throws BakeFileError naming `path`.
void write_bake_file(const std::string& path, const BakeFile& file);
BakeFile read_bake_file(const std::string& path);

// The whole bake from all its chunks, in any order; throws BakeFileError naming the part that
// does not fit (another bake, a repeated or missing chunk). The result is byte-identical to a
// single run's file.
BakeFile merge_bake_parts(const std::vector<BakeFile>& parts, const std::vector<std::string>& paths);

}  // namespace lg
