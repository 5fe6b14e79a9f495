// The .lgprobes file (docs/probe-format.md): the probes of every irradiance volume of a scene,
// baked whole or one chunk at a time, in the bake container (nodes/raytrace/bake_container.h,
// magic "LGPROBE1"). The header lists the volumes (frame, size, probe counts), the bake's
// settings, the scene, graph and environment it was baked with and the hash of the geometry, so a
// later load can tell a stale bake; the arrays hold every ProbeData field, probe by probe, the
// volumes' probes numbered one after the other. merge_probe_parts() checks that parts belong to
// one run and cover it exactly once.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "nodes/gi/probes/probe_bake.h"
#include "nodes/gi/probes/probe_grid.h"
#include "nodes/raytrace/bake_chunks.h"
#include "nodes/raytrace/bake_container.h"

namespace lg {

inline constexpr uint32_t max_probe_volumes = 65536;
inline constexpr uint32_t max_probes_per_axis = 256;  // as scene files allow
inline constexpr uint64_t max_file_probes = uint64_t(1) << 26;
inline constexpr uint32_t max_probe_rays = 1u << 20;
inline constexpr uint32_t max_probe_bounces = 1024;

struct ProbeFileHeader {
  std::string scene;           // the scene file as named on the command line
  std::string graph;           // the graph file, or "<default>"
  std::string environment;     // --env's file, or empty
  uint64_t geometry_hash = 0;  // world_mesh_hash() of the scene's geometry
  ProbeBakeSettings settings;
  std::vector<IrradianceVolumeData> volumes;
  uint64_t probes = 0;  // of every volume, together
  uint32_t chunk_index = 0, chunk_count = 1;
  PointRange range;  // the probes this file holds

  // The first probe of each volume in the numbering across volumes.
  std::vector<uint64_t> first_probes() const;
};

struct ProbeFile {
  ProbeFileHeader header;
  std::vector<ProbeData> probes;  // header.range.size()
};

// A header for chunk `index` of `count` of the probes of `volumes` (probes counted from them).
ProbeFileHeader make_probe_header(std::vector<IrradianceVolumeData> volumes, uint32_t index, uint32_t count);

std::string encode_probe_file(const ProbeFile& file);
// Throws BakeFileError naming `path`: unreadable, truncated, not a probe bake, counts out of
// range, non-finite values.
void write_probe_file(const std::string& path, const ProbeFile& file);
ProbeFile read_probe_file(const std::string& path);
// Whether `path` starts like a probe bake (merge tells the kinds of bake apart by it).
bool is_probe_file(const std::string& path);

// The whole bake from all its chunks, in any order; throws BakeFileError naming the part that
// does not fit (another run, a repeated or missing chunk). Byte-identical to a single run's file.
ProbeFile merge_probe_parts(const std::vector<ProbeFile>& parts, const std::vector<std::string>& paths);

// The grids of a whole bake, each with its probes.
std::vector<ProbeGrid> probe_grids(const ProbeFile& whole);
// The other way: a whole bake (chunk 1 of 1) holding `grids`' volumes and probes, baked with
// `settings`; scene, graph, environment and geometry hash are left for the caller to name.
ProbeFile whole_probe_file(std::span<const ProbeGrid> grids, const ProbeBakeSettings& settings);

}  // namespace lg
