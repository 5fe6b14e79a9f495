// `lumagraph reference`: the path-traced ground truth of a scene seen through its camera, with
// the environment of a graph (docs/path-tracer.md), whole or one band of rows at a time, and
// `lumagraph reference merge` to assemble the bands.
#include <cstdio>
#include <exception>

#include "api/world_loading.h"
#include "cli/args.h"
#include "cli/commands.h"
#include "cli/graph_environment.h"
#include "cli/graph_input.h"
#include "cli/progress_line.h"
#include "nodes/gi/path_tracer/reference_file.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph reference [SCENE] --out FILE.exr [options]
       lumagraph reference merge PART... --out FILE.exr [--aov AOV]

Path-traces the scene (.json, .gltf, .glb, .obj; default: the embedded default scene) through
its camera on all cores: one path per sample through each pixel centre (the G-buffer's pixels),
next-event estimation and BRDF sampling with multiple importance sampling, Russian roulette.
The environment is the graph's (env.sky's sky and sun, or env.load's file); the graph's
scene.gbuffer says whether back faces are culled for the camera. FILE.exr gets the chosen AOV
as 32-bit floats and FILE.stderr.exr beside it the standard error of each pixel's mean.

options:
  --graph GRAPH       the graph whose environment to use (default: the embedded default graph)
  --env FILE          environment (.hdr, .exr) for every env.load node of the graph
  --spp N             paths per pixel, 1 to 1048576 (default 64)
  --bounces B         surface interactions per path, 1 to 1024: 1 is direct light only (default 8)
  --aov AOV           radiance (default, the sum of the others), emission (seen without a
                      reflection: emissive surfaces, the environment), direct (the scene's lights
                      reflected once, shadowed), indirect_diffuse (the diffuse lobe on all other
                      light), specular (the specular lobe on all other light)
  --size WxH          image size (default 1280x720)
  --seed S            random seed (default 1); the same seed gives the same image on any split
  --chunk I/N         trace only band I of N of the rows and write a part file (every AOV) to
                      --out; merge the N parts with `lumagraph reference merge`
  --asset-root DIR    allow file paths in the graph and the scene under DIR (repeatable)

exit status: 0 written, 1 usage error, 2 invalid scene, graph or part files, 3 writing failed
)";

ArgSpec reference_arg_spec() {
  return {{"--help"},
          {"--graph", "--env", "--spp", "--bounces", "--aov", "--size", "--seed", "--chunk", "--out", "--asset-root"},
          {"--asset-root"}};
}

struct ReferenceArgs {
  PathTracerOptions trace;
  ReferenceAov aov = ReferenceAov::radiance;
  uint32_t chunk_index = 0, chunk_count = 1;
  bool chunked = false;
};

std::optional<std::string> read_reference_options(const Args& args, ReferenceArgs& o) {
  uint64_t spp = o.trace.samples_per_pixel, bounces = o.trace.max_bounces;
  if (auto bad = read_count(args, "--spp", 1u << 20, spp)) return bad;
  if (auto bad = read_count(args, "--bounces", 1024, bounces)) return bad;
  o.trace.samples_per_pixel = uint32_t(spp), o.trace.max_bounces = uint32_t(bounces);
  if (auto v = args.value("--aov")) {
    auto aov = parse_reference_aov(*v);
    if (!aov) return "--aov expects radiance, emission, direct, indirect_diffuse or specular; got '" + *v + "'";
    o.aov = *aov;
  }
  if (auto bad = read_seed(args, o.trace.seed)) return bad;
  FrameSize frame{1280, 720};
  if (auto bad = read_frame_size(args, frame)) return bad;
  o.trace.width = frame.width, o.trace.height = frame.height;
  if (auto bad = read_chunk(args, max_reference_chunks, o.chunk_index, o.chunk_count, o.chunked)) return bad;
  if (o.chunked) chunk_rows(o.trace.height, o.chunk_index, o.chunk_count, o.trace.row_begin, o.trace.row_end);
  return std::nullopt;
}

int merge_command(const Args& args, const std::string& out) {
  ReferenceArgs options;
  if (auto bad = read_reference_options(args, options)) return usage_error("reference", *bad);
  const std::vector<std::string> paths(args.positional.begin() + 1, args.positional.end());
  if (paths.empty()) return usage_error("reference", "merge needs the part files to merge");
  ReferenceImage image;
  try {
    std::vector<ReferencePart> parts;
    for (const std::string& path : paths) parts.push_back(read_reference_part(path));
    image = merge_reference_parts(parts, paths);
  } catch (const ReferenceFileError& e) {
    std::fprintf(stderr, "lumagraph reference: %s\n", e.what());
    return exit_invalid;
  }
  try {
    for (const std::string& path : write_reference_exr(out, image, options.aov))
      std::printf("wrote %s\n", path.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph reference: %s\n", e.what());
    return exit_write;
  }
  return exit_ok;
}

// What must agree between the chunks of one run.
std::string run_identity(const std::string& scene, const std::string& graph, const std::string& env,
                         const PathTracerOptions& o) {
  char text[256];
  std::snprintf(text, sizeof text, " spp=%u bounces=%u seed=%llu cull=%d", o.samples_per_pixel, o.max_bounces,
                static_cast<unsigned long long>(o.seed), int(o.cull_backfaces));
  return "scene=" + scene + " graph=" + graph + " env=" + env + text;
}

}  // namespace

int reference_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(argv, reference_arg_spec(), &error);
  if (!args) return usage_error("reference", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  const std::optional<std::string> out = args->value("--out");
  if (!out) return usage_error("reference", "--out FILE is required");
  if (!args->positional.empty() && args->positional[0] == "merge") return merge_command(*args, *out);
  if (args->positional.size() > 1)
    return usage_error("reference", "expected one scene file, got " + std::to_string(args->positional.size()));
  ReferenceArgs options;
  if (auto bad = read_reference_options(*args, options)) return usage_error("reference", *bad);
  const std::string scene_path = args->positional.empty() ? "" : args->positional[0];

  std::optional<PathScene> scene;
  try {
    const World world = scene_path.empty()
                            ? default_world()
                            : load_world(scene_path, renderer_world_options(scene_path, args->values("--asset-root")));
    SceneView view = make_scene_view(world, float(options.trace.width) / float(options.trace.height));

    // The graph, compiled for this scene, says which environment the raster path lights it with.
    std::optional<PathEnvironment> environment = load_graph_environment(
        *args, view, {options.trace.width, options.trace.height}, "reference", options.trace.cull_backfaces);
    if (!environment) return exit_invalid;
    scene.emplace(std::move(view), std::move(*environment));
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph reference: %s: error: %s\n",
                 scene_path.empty() ? "<default scene>" : scene_path.c_str(), e.what());
    return exit_invalid;
  }

  const PathTracerOptions& o = options.trace;
  ProgressLine progress("reference", "pixels", uint64_t(o.row_end == 0 ? o.height : o.row_end - o.row_begin) * o.width);
  ReferencePart part;
  part.image = trace_reference(*scene, o, [&](size_t done) { progress.update(done); });
  progress.finish();
  const ReferenceImage& image = part.image;
  std::printf("traced %ux%u pixels (rows %u to %u of %u), %u paths each, at most %u bounces, in %.2f s\n", image.width,
              image.row_end - image.row_begin, image.row_begin, image.row_end, image.height, o.samples_per_pixel,
              o.max_bounces, progress.seconds());
  if (image.non_finite_samples)
    std::fprintf(stderr, "lumagraph reference: warning: %llu paths gave NaN or Inf and were counted as 0\n",
                 static_cast<unsigned long long>(image.non_finite_samples));
  try {
    if (options.chunked) {
      part.run = run_identity(scene_path, args->value("--graph").value_or("<default>"),
                              args->value("--env").value_or("<graph's>"), o);
      part.chunk_index = options.chunk_index, part.chunk_count = options.chunk_count;
      write_reference_part(*out, part);
      std::printf("wrote %s\n", out->c_str());
    } else {
      for (const std::string& path : write_reference_exr(*out, image, options.aov))
        std::printf("wrote %s\n", path.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph reference: %s\n", e.what());
    return exit_write;
  }
  return exit_ok;
}

}  // namespace lg::cli
