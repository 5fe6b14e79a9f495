// `lumagraph bake`: ambient occlusion and bent normals of a mesh or scene baked with Embree per
// vertex, per lightmap texel or in a volume, whole or one chunk at a time, and `lumagraph bake
// merge` to assemble the chunks (docs/bake-format.md, docs/baking.md). `--mode probes` goes to
// probe_bake_command.cpp, `--mode prt` to prt_bake_command.cpp.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/probe_bake_command.h"
#include "cli/progress_line.h"
#include "cli/prt_bake_command.h"
#include "nodes/gi/probes/probe_file.h"
#include "nodes/gi/prt/prt_file.h"
#include "nodes/occlusion/bake/bake_file.h"
#include "nodes/occlusion/bake/bake_outputs.h"
#include "nodes/occlusion/bake/bake_run.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph bake MESH_OR_SCENE --out PATH [options]
       lumagraph bake SCENE --mode probes --out PATH.lgprobes [probe options]
       lumagraph bake MESH_OR_SCENE --mode prt --out PATH.lgprt [transfer options]
       lumagraph bake merge PART... --out PATH

Bakes ambient visibility k_A (cosine-weighted, stratified Monte Carlo with Embree on all cores)
and bent normals of a mesh (.obj, .gltf, .glb) or scene file (.json), every draw in world space.
PATH receives the .lgbake file (docs/bake-format.md); texel bakes also write PATH's stem .png
(k_A) and .exr (bent normal, k_A), volume bakes a .vti (VTK image data) beside it.

options:
  --mode vertex|texel|volume  per vertex (default), per texel of a generated lightmap UV set,
                        or at the points of a grid around the geometry (over the whole sphere;
                        points inside geometry are marked invalid)
  --rays N              rays per point, 1 to 1048576 (default 256)
  --max-distance D      rays end at D (default: infinite)
  --falloff none|obscurance
                        a hit within D occludes fully (none, default) or by the obscurance
                        curve 1 - (1 - t/D)^2 (needs --max-distance)
  --resolution R        texel: lightmap size R (R x R texels, default 512, at most 8192);
                        volume: points along the longest axis (default 32) or NXxNYxNZ
                        (2 to 1024 each)
  --seed S              random seed (default 1); same seed, same result on any machine split
  --chunk I/N           bake only chunk I of N (0 <= I < N): a contiguous range of the points;
                        merge the N part files with `lumagraph bake merge`
  --out PATH            the output file (required)
  --asset-root DIR      allow the scene file's paths under DIR (repeatable); the bakes a scene
                        file already names ("occlusion") are not read: a bake traces geometry

--mode probes bakes every probe of every irradiance_volume of a scene file with the path
tracer's transport (docs/probe-format.md): PATH.lgprobes, and PATH.vti (one volume) or
PATH.0.vti, PATH.1.vti... beside it. Its options: --rays N (per probe, 1 to 1048576, default
256), --bounces B (1 to 1024, default 3), --seed, --chunk, --asset-root as above, and
  --graph GRAPH         the graph whose environment lights the scene (default: the embedded
                        default graph), as `lumagraph reference`
  --env FILE            environment (.hdr, .exr) for every env.load node of the graph

--mode prt bakes the diffuse transfer vectors of every vertex for gi.prt (docs/prt.md) into
PATH.lgprt. Its options: --rays N (per vertex, 1 to 1048576, default 256), --seed, --chunk,
--asset-root as above, and
  --transfer unshadowed|shadowed|interreflected
                        the cosine lobe alone, cut by the scene's shadows, or with the light the
                        scene reflects onto the vertex too (default interreflected)
  --order N             highest SH band, 2 to 4 (default 3)
  --bounces B           interreflected: diffuse bounces, 1 to 64 (default 2)

`bake merge PART... --out PATH` checks that the parts are all the chunks of one bake, each
once, and writes the whole bake, byte-identical to a single run with the same options (occlusion,
probe and PRT bakes alike).

exit status: 0 baked, 1 usage error, 2 invalid input (mesh, scene or part files), 3 writing failed
)";

ArgSpec bake_arg_spec() {
  return {{"--help"},
          {"--mode", "--rays", "--bounces", "--max-distance", "--falloff", "--resolution", "--seed", "--chunk", "--out",
           "--asset-root", "--graph", "--env", "--order", "--transfer"},
          {"--asset-root"}};
}

struct BakeOptions {
  BakeMode mode = BakeMode::vertex;
  OcclusionSettings occlusion;
  std::array<uint32_t, 3> resolution{0, 0, 0};
  uint64_t seed = 1;
  uint32_t chunk_index = 0, chunk_count = 1;
  bool chunked = false;
};

// Reads the options; returns an error message for a bad value.
std::optional<std::string> read_bake_options(const Args& args, BakeOptions& o) {
  if (auto mode = args.value("--mode")) {
    auto parsed = parse_bake_mode(*mode);
    if (!parsed) return "--mode expects vertex, texel, volume, probes or prt; got '" + *mode + "'";
    o.mode = *parsed;
  }
  for (const char* probes_only : {"--bounces", "--graph", "--env"})
    if (args.value(probes_only)) return std::string(probes_only) + " applies to --mode probes only";
  for (const char* prt_only : {"--order", "--transfer"})
    if (args.value(prt_only)) return std::string(prt_only) + " applies to --mode prt only";
  uint64_t rays = uint64_t(o.occlusion.rays);
  if (auto bad = read_count(args, "--rays", max_rays_per_point, rays)) return bad;
  o.occlusion.rays = int(rays);
  if (auto distance = args.value("--max-distance")) {
    char tail = 0;
    float d = 0;
    if (std::sscanf(distance->c_str(), "%f%c", &d, &tail) != 1 || !std::isfinite(d) || d <= 0.0f)
      return "--max-distance expects a positive number; got '" + *distance + "'";
    o.occlusion.max_distance = d;
  }
  if (auto falloff = args.value("--falloff")) {
    if (*falloff == "obscurance")
      o.occlusion.falloff = OcclusionFalloff::obscurance;
    else if (*falloff != "none")
      return "--falloff expects none or obscurance; got '" + *falloff + "'";
  }
  if (o.occlusion.falloff == OcclusionFalloff::obscurance && std::isinf(o.occlusion.max_distance))
    return "--falloff obscurance needs --max-distance";
  if (auto bad = read_seed(args, o.seed)) return bad;
  if (auto resolution = args.value("--resolution")) {
    uint64_t n = 0;
    if (o.mode == BakeMode::vertex) return "--resolution applies to texel and volume bakes, not vertex";
    unsigned x = 0, y = 0, z = 0;
    char tail = 0;
    if (o.mode == BakeMode::volume && std::sscanf(resolution->c_str(), "%ux%ux%u%c", &x, &y, &z, &tail) == 3) {
      o.resolution = {x, y, z};
    } else if (parse_unsigned(*resolution, std::numeric_limits<uint32_t>::max(), n)) {
      o.resolution = {uint32_t(n), 0, 0};
    } else {
      return o.mode == BakeMode::texel ? "--resolution expects the lightmap size R; got '" + *resolution + "'"
                                       : "--resolution expects N or NXxNYxNZ; got '" + *resolution + "'";
    }
  }
  if (o.resolution[0] == 0) o.resolution = {o.mode == BakeMode::texel ? 512u : 32u, 0, 0};
  if (auto bad = read_chunk(args, max_bake_chunks, o.chunk_index, o.chunk_count, o.chunked)) return bad;
  return std::nullopt;
}

int merge_command(const std::vector<std::string>& parts, const std::string& out) {
  if (parts.empty()) return usage_error("bake", "merge needs the part files to merge");
  if (is_probe_file(parts[0])) return probe_merge_command(parts, out);
  if (is_prt_file(parts[0])) return prt_merge_command(parts, out);
  try {
    std::vector<BakeFile> files;
    for (const std::string& path : parts) files.push_back(read_bake_file(path));
    const BakeFile merged = merge_bake_parts(files, parts);
    try {
      for (const std::string& path : write_bake_outputs(out, merged)) std::printf("wrote %s\n", path.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
      return exit_write;
    }
    std::printf("merged %zu parts: %llu points\n", parts.size(), static_cast<unsigned long long>(merged.header.points));
  } catch (const BakeFileError& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_invalid;
  }
  return exit_ok;
}

// A scene file's paths may point into its folder and every --asset-root. Its "occlusion" keys are
// accepted unread: baking traces geometry, and baking a scene again must not need its old bakes.
WorldLoadOptions world_load_options(const Args& args, const std::string& input) {
  WorldLoadOptions options;
  options.asset_roots.roots = args.values("--asset-root");
  if (!options.asset_roots.roots.empty())
    options.asset_roots.roots.push_back(std::filesystem::absolute(input).parent_path().string());
  options.read_occlusion = [](const std::string&, std::span<const MeshData* const>, std::span<const glm::mat4>) {
    return std::vector<std::shared_ptr<const MeshOcclusion>>{};
  };
  return options;
}

}  // namespace

int bake_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(argv, bake_arg_spec(), &error);
  if (!args) return usage_error("bake", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  const std::optional<std::string> out = args->value("--out");
  if (!out) return usage_error("bake", "--out PATH is required");
  if (!args->positional.empty() && args->positional[0] == "merge")
    return merge_command({args->positional.begin() + 1, args->positional.end()}, *out);
  if (args->positional.size() != 1)
    return usage_error("bake", "expected one mesh or scene file, got " + std::to_string(args->positional.size()));
  const std::string& input = args->positional[0];
  if (args->value("--mode") == "probes")
    return probe_bake_command(*args, input, world_load_options(*args, input), *out);
  if (args->value("--mode") == "prt") return prt_bake_command(*args, input, world_load_options(*args, input), *out);
  BakeOptions options;
  if (auto bad = read_bake_options(*args, options)) return usage_error("bake", *bad);

  WorldMesh mesh;
  std::optional<BakeDomain> domain;
  std::optional<RayScene> scene;
  try {
    const SceneView view = make_scene_view(load_world(input, world_load_options(*args, input)), 1.0f);
    mesh = make_world_mesh(view);
    if (options.mode == BakeMode::vertex) domain = BakeDomain::vertices(mesh);
    if (options.mode == BakeMode::texel) domain = BakeDomain::lightmap(mesh, options.resolution[0]);
    if (options.mode == BakeMode::volume) domain = BakeDomain::volume(mesh, options.resolution);
    scene.emplace(mesh, view);  // alpha-tested materials let the bake's rays through
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: %s: error: %s\n", input.c_str(), e.what());
    return exit_invalid;
  }

  BakeFile file;
  file.header =
      make_bake_header(*domain, mesh, input, options.occlusion, options.seed, options.chunk_index, options.chunk_count);
  if (options.mode == BakeMode::texel) file.lightmap_uvs = domain->lightmap_uvs();
  const PointRange range = file.header.range;
  ProgressLine progress("bake", "points", range.size());
  file.data =
      run_bake(*scene, *domain, options.occlusion, options.seed, range, [&](uint64_t done) { progress.update(done); });
  progress.finish();
  const double seconds = progress.seconds();

  double visibility_sum = 0.0;
  size_t valid = 0;
  for (size_t i = 0; i < file.data.size(); ++i)
    if (file.data.valid[i] > 0.0f) visibility_sum += file.data.visibility[i], ++valid;
  std::printf(
      "baked %llu %s points of %s (chunk %u/%u: %llu to %llu of %llu), %d rays each, in %.2f s; mean k_A %.4f over %zu "
      "valid points\n",
      static_cast<unsigned long long>(range.size()), bake_mode_name(options.mode), input.c_str(), options.chunk_index,
      options.chunk_count, static_cast<unsigned long long>(range.begin), static_cast<unsigned long long>(range.end),
      static_cast<unsigned long long>(file.header.points), options.occlusion.rays, seconds,
      valid ? visibility_sum / valid : 0.0, valid);
  try {
    if (options.chunked) {
      write_bake_file(*out, file);
      std::printf("wrote %s\n", out->c_str());
    } else {
      for (const std::string& path : write_bake_outputs(*out, file)) std::printf("wrote %s\n", path.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph bake: error: %s\n", e.what());
    return exit_write;
  }
  return exit_ok;
}

}  // namespace lg::cli
