// The .lgprt file (docs/prt.md): per-vertex transfer vectors of a world mesh, baked whole or one
// chunk (a contiguous range of vertices) at a time, in the bake container
// (nodes/raytrace/bake_container.h, magic "LGPRT001"). The header names the input, the hash of
// its geometry (world_mesh_hash), the settings, each draw's vertices and the chunk; the arrays
// are "transfer" (3 (order + 1)^2 floats a vertex, prt_bake.h) and "valid" (1 a vertex).
// Files are untrusted: the reader refuses, naming the file and what is wrong, anything that is
// not exactly such a file (counts out of range, sizes that disagree, non-finite values).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nodes/gi/prt/prt_bake.h"
#include "nodes/raytrace/bake_chunks.h"
#include "nodes/raytrace/bake_container.h"
#include "nodes/raytrace/world_mesh.h"

namespace lg {

// At most 2^26 vertices in one bake (7.5 GB of order-4 transfer).
inline constexpr uint64_t kPrtMaxVertices = uint64_t(1) << 26;

struct PrtFileHeader {
  std::string input;        // the scene or mesh file as named on the command line
  uint64_t input_hash = 0;  // world_mesh_hash() of its geometry
  PrtSettings settings;
  uint64_t vertices = 0;               // of the whole bake
  std::vector<WorldMesh::Part> parts;  // each draw's vertices
  uint32_t chunk_index = 0, chunk_count = 1;
  PointRange range;  // the vertices this file holds
};

struct PrtFile {
  PrtFileHeader header;
  PrtData data;  // header.range.size() vertices
};

// The header of chunk `index` of `count` of a bake of `mesh`.
PrtFileHeader make_prt_header(const WorldMesh& mesh, const std::string& input, const PrtSettings& settings,
                              uint32_t index, uint32_t count);

std::string encode_prt_file(const PrtFile& file);
// Throw BakeFileError naming `path`.
void write_prt_file(const std::string& path, const PrtFile& file);
PrtFile read_prt_file(const std::string& path);
bool is_prt_file(const std::string& path);

// The whole bake from all its chunks, in any order; throws BakeFileError naming the part that
// does not fit. Byte-identical to a single run's file.
PrtFile merge_prt_parts(const std::vector<PrtFile>& parts, const std::vector<std::string>& paths);

}  // namespace lg
