#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "api/renderer.h"
#include "api/world_loading.h"
#include "cli/commands.h"
#include "cli/dump_outputs.h"
#include "cli/graph_input.h"
#include "cli/validation_report.h"
#include "graph/json_writer.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph render [GRAPH] [options]

Renders frames of a graph on a scene and writes the main output as an image. With no GRAPH,
the embedded default graph (examples/default.json); with no --scene, the embedded default
scene (a room with spheres, a bunny, a sun, a sphere and a tube light under a procedural sky).

options:
  --scene FILE        scene file (.json), glTF (.gltf, .glb) or OBJ (.obj) to render
  --env FILE          environment (.hdr, .exr) for every env.load node of the graph
  --size WxH          frame size in pixels (default 1280x720)
  --frames N          frames to render (default 1); temporal nodes settle over frames
  --frame-seconds S   the time between frames, in seconds (default 1/60): how far
                      post.exposure adapts from one frame to the next
  --out FILE          image to write: .png (default out.png), .exr or .hdr
  --dump DIR          write every node output port of the last frame: textures as EXR,
                      3D textures as VTK image data (.vti, one a mip), SH and scalars
                      as JSON (turns memory aliasing off so all survive; optional
                      outputs, as gi.lpv's and gi.voxel's volumes, are written too)
  --stats FILE        write the last frame's per-pass GPU times and memory as JSON
  --device NAME       the GPU whose name contains NAME (default: the first suitable)
  --validate          run with the Vulkan validation layer; any message fails the run
  --asset-root DIR    allow file paths in params and in the scene file under DIR
                      (repeatable; the scene file's own folder stays allowed)
  --no-alias          give every transient resource its own memory
  --no-pipeline-cache do not read or write the pipeline cache and static results on
                      disk ($XDG_CACHE_HOME/lumagraph; LUMAGRAPH_PIPELINE_CACHE=off does the same)

exit status: 0 rendered, 1 usage error, 2 invalid graph or scene, 3 the GPU or a node failed
)";

constexpr int exit_runtime = 3;

ArgSpec render_arg_spec() {
  return {{"--help", "--validate", "--no-alias", "--no-pipeline-cache"},
          {"--scene", "--env", "--size", "--frames", "--frame-seconds", "--out", "--dump", "--stats", "--device",
           "--asset-root"},
          {"--asset-root"}};
}

// Points every env.load node at `path`, and allows its folder as an asset root.
void use_environment(Graph& graph, const std::string& path, AssetRoots& roots) {
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  for (GraphNode& node : graph.nodes)
    if (node.type == "env.load") node.params.set("path", absolute);
  roots.roots.push_back(std::filesystem::path(absolute).parent_path().string());
}

}  // namespace

int render_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(argv, render_arg_spec(), &error);
  if (!args) return usage_error("render", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (args->positional.size() > 1)
    return usage_error("render", "expected one graph file, got " + std::to_string(args->positional.size()));
  FrameSize frame;
  if (auto bad = read_frame_size(*args, frame)) return usage_error("render", *bad);
  unsigned frames = 1;
  if (auto n = args->value("--frames")) {
    char tail = 0;
    if (std::sscanf(n->c_str(), "%u%c", &frames, &tail) != 1 || frames == 0 || frames > 100000)
      return usage_error("render", "--frames expects a count from 1 to 100000; got '" + *n + "'");
  }
  FrameTiming timing;
  if (auto text = args->value("--frame-seconds")) {
    char tail = 0;
    double seconds = 0;
    // At most an hour: more is a typo, and float(seconds) stays finite and above 0.
    if (std::sscanf(text->c_str(), "%lf%c", &seconds, &tail) != 1 || !std::isfinite(seconds) || !(float(seconds) > 0) ||
        seconds > 3600)
      return usage_error("render",
                         "--frame-seconds expects a time in seconds above 0 and at most 3600; got '" + *text + "'");
    timing.seconds = float(seconds);
  }
  const std::string out = args->value("--out").value_or("out.png");

  std::optional<Graph> graph = load_graph_argument_or_print(*args);
  if (!graph) return exit_invalid;
  RendererOptions options;
  options.device.validation = args->has("--validate");
  options.device.device_name = args->value("--device").value_or("");
  options.asset_roots.roots = args->values("--asset-root");
  options.alias = !args->has("--no-alias") && !args->value("--dump");
  options.keep_optional_outputs = args->value("--dump").has_value();
  options.pipeline_cache_on_disk = !args->has("--no-pipeline-cache");
  if (auto env = args->value("--env")) use_environment(*graph, *env, options.asset_roots);

  World world;
  try {
    world = args->value("--scene")
                ? load_world(*args->value("--scene"),
                             renderer_world_options(*args->value("--scene"), args->values("--asset-root")))
                : default_world();
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  }
  for (const auto& w : world.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());

  size_t validation_messages = 0;
  try {
    Renderer renderer(options);
    auto print_warnings = [&] {
      for (const std::string& w : renderer.take_warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
    };
    print_warnings();
    renderer.set_graph(std::move(*graph));
    const bool progress = frames > 1 && isatty(STDERR_FILENO);
    FrameStats stats;
    for (unsigned f = 0; f < frames; ++f) {
      stats = renderer.render(world, frame, timing);
      print_validation("render", renderer.context(), validation_messages);
      print_warnings();
      if (progress) std::fprintf(stderr, "\rframe %u/%u  %.1f ms GPU", f + 1, frames, stats.gpu_ms);
    }
    if (progress) std::fputc('\n', stderr);
    std::fputs(frame_stats_text(stats).c_str(), stdout);
    const PipelineCache& pipelines = renderer.context().pipelines();
    std::printf("pipelines: %llu made, %llu of them from the driver's cache\n",
                static_cast<unsigned long long>(pipelines.created()),
                static_cast<unsigned long long>(pipelines.driver_cache_hits()));

    std::vector<float> pixels = renderer.read_output();
    const Image& image = renderer.output_image();
    save_image(out, image.desc().width, image.desc().height, pixels);
    std::printf("wrote %s (%ux%u)\n", out.c_str(), image.desc().width, image.desc().height);
    if (auto dir = args->value("--dump")) dump_outputs(renderer.executor(), *dir);
    if (auto file = args->value("--stats")) {
      std::string write_error;
      if (!write_file_atomically(*file, write_json(frame_stats_json(stats)), &write_error)) {
        std::fprintf(stderr, "lumagraph render: %s\n", write_error.c_str());
        return exit_runtime;
      }
    }
    print_validation("render", renderer.context(), validation_messages);
  } catch (const GraphError& e) {
    std::fputs(e.what(), stderr);
    return exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph render: error: %s\n", e.what());
    return exit_runtime;
  }
  if (validation_messages > 0) {
    std::fprintf(stderr, "lumagraph render: %zu validation message%s\n", validation_messages,
                 validation_messages == 1 ? "" : "s");
    return exit_runtime;
  }
  return exit_ok;
}

}  // namespace lg::cli
