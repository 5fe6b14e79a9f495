// `lumagraph bake --mode probes`: every probe of every irradiance volume of a scene, numbered
// across the volumes so that chunks split them evenly, and the merge of the chunks.
#include "cli/probe_bake_command.h"

#include <cstdio>
#include <exception>

#include "cli/commands.h"
#include "cli/graph_environment.h"
#include "cli/progress_line.h"
#include "nodes/gi/probes/probe_outputs.h"
#include "nodes/raytrace/world_mesh.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

struct ProbeOptions {
  ProbeBakeSettings settings;
  uint32_t chunk_index = 0, chunk_count = 1;
  bool chunked = false;
};

std::optional<std::string> read_probe_options(const Args& args, ProbeOptions& o) {
  for (const char* occlusion_only : {"--max-distance", "--falloff", "--resolution"})
    if (args.value(occlusion_only))
      return std::string(occlusion_only) + " applies to occlusion bakes, not --mode probes";
  for (const char* prt_only : {"--order", "--transfer"})
    if (args.value(prt_only)) return std::string(prt_only) + " applies to --mode prt only";
  uint64_t rays = o.settings.rays, bounces = o.settings.bounces;
  if (auto bad = read_count(args, "--rays", max_probe_rays, rays)) return bad;
  if (auto bad = read_count(args, "--bounces", max_probe_bounces, bounces)) return bad;
  o.settings.rays = uint32_t(rays), o.settings.bounces = uint32_t(bounces);
  if (auto bad = read_seed(args, o.settings.seed)) return bad;
  if (auto bad = read_chunk(args, max_bake_chunks, o.chunk_index, o.chunk_count, o.chunked)) return bad;
  return std::nullopt;
}

// Bakes the file's range of probes, volume by volume, into file.probes. (bake_probes fills a
// whole grid's storage; a chunk keeps only its own probes of it.)
void bake_range(const PathScene& scene, ProbeFile& file, const ProgressLine& progress) {
  const ProbeFileHeader& h = file.header;
  const std::vector<uint64_t> first = h.first_probes();
  uint64_t done_before = 0;
  for (size_t v = 0; v < h.volumes.size(); ++v) {
    ProbeGrid grid(h.volumes[v]);
    const uint64_t begin = std::max(h.range.begin, first[v]),
                   end = std::min(h.range.end, first[v] + grid.probe_count());
    if (begin >= end) continue;
    bake_probes(scene, grid, h.settings, begin - first[v], end - first[v],
                [&](size_t done) { progress.update(done_before + done); });
    file.probes.insert(file.probes.end(), grid.probes.begin() + (begin - first[v]),
                       grid.probes.begin() + (end - first[v]));
    done_before += end - begin;
  }
}

int write_outputs(const std::string& out, const ProbeFile& file, bool whole) {
  try {
    if (whole) {
      for (const std::string& path : write_probe_outputs(out, file)) std::printf("wrote %s\n", path.c_str());
    } else {
      write_probe_file(out, file);
      std::printf("wrote %s\n", out.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_write;
  }
  return exit_ok;
}

}  // namespace

int probe_bake_command(const Args& args, const std::string& input, const WorldLoadOptions& load_options,
                       const std::string& out) {
  ProbeOptions options;
  if (auto bad = read_probe_options(args, options)) return usage_error("bake", *bad);
  ProbeFile file;
  std::optional<PathScene> scene;
  try {
    SceneView view = make_scene_view(load_world(input, load_options), 16.0f / 9.0f);
    if (view.irradiance_volumes.empty()) {
      std::fprintf(stderr,
                   "lumagraph bake: %s: error: the scene has no irradiance volume to bake; add an entity with an "
                   "\"irradiance_volume\" (docs/scene-format.md)\n",
                   input.c_str());
      return exit_invalid;
    }
    file.header = make_probe_header(view.irradiance_volumes, options.chunk_index, options.chunk_count);
    file.header.scene = input;
    file.header.graph = args.value("--graph").value_or("<default>");
    file.header.environment = args.value("--env").value_or("");
    file.header.geometry_hash = world_mesh_hash(make_world_mesh(view));
    file.header.settings = options.settings;
    bool cull_backfaces = true;  // probes see both sides of every surface: the camera's culling does not apply
    std::optional<PathEnvironment> environment =
        load_graph_environment(args, view, {1280, 720}, "bake", cull_backfaces);
    if (!environment) return exit_invalid;
    scene.emplace(std::move(view), std::move(*environment));
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: %s: error: %s\n", input.c_str(), e.what());
    return exit_invalid;
  }

  const ProbeFileHeader& h = file.header;
  ProgressLine progress("bake", "probes", h.range.size());
  bake_range(*scene, file, progress);
  progress.finish();
  size_t active = 0, relocated = 0;
  for (const ProbeData& p : file.probes) {
    active += p.active;
    relocated += p.active && p.offset != glm::vec3(0.0f);
  }
  std::printf(
      "baked %llu probes of %s (volumes: %zu; chunk %u/%u: %llu to %llu of %llu), %u rays each, at most %u "
      "bounces, in %.2f s: %zu active (%zu of them relocated), %zu off\n",
      static_cast<unsigned long long>(h.range.size()), input.c_str(), h.volumes.size(), h.chunk_index, h.chunk_count,
      static_cast<unsigned long long>(h.range.begin), static_cast<unsigned long long>(h.range.end),
      static_cast<unsigned long long>(h.probes), h.settings.rays, h.settings.bounces, progress.seconds(), active,
      relocated, file.probes.size() - active);
  return write_outputs(out, file, !options.chunked);
}

int probe_merge_command(const std::vector<std::string>& parts, const std::string& out) {
  ProbeFile merged;
  try {
    std::vector<ProbeFile> files;
    for (const std::string& path : parts) files.push_back(read_probe_file(path));
    merged = merge_probe_parts(files, parts);
  } catch (const BakeFileError& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_invalid;
  }
  if (int status = write_outputs(out, merged, true); status != exit_ok) return status;
  std::printf("merged %zu parts: %llu probes\n", parts.size(), static_cast<unsigned long long>(merged.header.probes));
  return exit_ok;
}

}  // namespace lg::cli
