// `lumagraph soak`: renders a graph frame after frame, as a game runs it, with a hot reload of a
// changed graph file every N frames and a change of world every M, and writes resident and
// device memory per frame as CSV. It fails when either grows by more than 1% after the warm-up,
// when the output holds a non-finite value or when validation reports anything.
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "api/renderer.h"
#include "api/world_loading.h"
#include "cli/commands.h"
#include "cli/graph_input.h"
#include "cli/validation_report.h"
#include "graph/graph_io.h"
#include "graph/json_writer.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/scene_error.h"

namespace lg::cli {
namespace {

constexpr const char* help = R"(usage: lumagraph soak [GRAPH] [options]

Renders GRAPH (default: the embedded default graph) frame after frame, as a game does, and
records memory: every --reload-every frames the graph file is rewritten with a new name and
hot-reloaded (compiled again, static results carried over), every --world-every frames the world
changes (between the default world and --scene, or a rebuilt default world without it). Each
frame's output is read back and checked for non-finite values. Writes one CSV row per frame:
frame, resident memory (MiB), device memory (MiB), GPU time (ms), whether the frame reloaded or
changed world, and the C heap's bytes in use and held from the system (MiB; glibc's mallinfo2),
which tell a leak (in use grows) from the allocator keeping freed memory (only held grows). The reloaded copy of the graph lives in a temporary folder, so a
graph's relative file params must be absolute or under --asset-root.

options:
  --scene FILE        the second world (.json scene file, glTF or OBJ)
  --size WxH          frame size in pixels (default 64x36)
  --frames N          frames to render (default 10000)
  --reload-every N    hot reload every N frames (default 100; 0: never)
  --world-every N     change world every N frames (default 500; 0: never)
  --warmup N          frames before memory is held to the 1% limit (default: a tenth)
  --csv FILE          where to write the rows (default soak.csv)
  --validate          Vulkan validation on; any message fails the run
  --asset-root DIR    allow file paths in params and the scene under DIR (repeatable)

exit status: 0 flat and clean, 1 usage error, 2 invalid graph or scene, 3 a frame failed,
memory grew, a value was not finite or validation reported something
)";

constexpr int exit_failed = 3;

uint64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * uint64_t(sysconf(_SC_PAGESIZE));
}

struct HeapBytes {
  double in_use_mib = 0, held_mib = 0;
};

HeapBytes heap_bytes() {
  const struct mallinfo2 info = mallinfo2();
  const double mib = 1 << 20;
  return {double(info.uordblks + info.hblkhd) / mib, double(info.arena + info.hblkhd) / mib};
}

size_t non_finite_values(const std::vector<float>& rgba) {
  return size_t(std::count_if(rgba.begin(), rgba.end(), [](float v) { return !std::isfinite(v); }));
}

struct Peak {
  double resident = 0, device = 0;
  void add(double r, double d) {
    resident = std::max(resident, r);
    device = std::max(device, d);
  }
};

double growth(double after, double before) {
  return before > 0 ? after / before - 1 : 0;
}

}  // namespace

int soak_command(const std::vector<std::string>& argv) {
  std::string error;
  auto args = parse_args(
      argv,
      {{"--help", "--validate"},
       {"--scene", "--size", "--frames", "--reload-every", "--world-every", "--warmup", "--csv", "--asset-root"},
       {"--asset-root"}},
      &error);
  if (!args) return usage_error("soak", error);
  if (args->has("--help")) {
    std::fputs(help, stdout);
    return exit_ok;
  }
  if (args->positional.size() > 1) return usage_error("soak", "expected one graph file");
  FrameSize size{64, 36};
  if (auto bad = read_frame_size(*args, size)) return usage_error("soak", *bad);
  uint64_t frames = 10000, reload_every = 100, world_every = 500;
  if (auto bad = read_count(*args, "--frames", 10'000'000, frames)) return usage_error("soak", *bad);
  for (auto [option, value] : {std::pair{"--reload-every", &reload_every}, std::pair{"--world-every", &world_every}})
    if (auto text = args->value(option); text && !parse_unsigned(*text, 10'000'000, *value))
      return usage_error("soak", std::string(option) + " expects a count (0: never); got '" + *text + "'");
  uint64_t warmup = frames / 10;
  if (auto text = args->value("--warmup"); text && (!parse_unsigned(*text, frames - 1, warmup)))
    return usage_error("soak", "--warmup expects a count below --frames; got '" + *text + "'");
  const std::string csv_path = args->value("--csv").value_or("soak.csv");

  std::optional<Graph> graph = load_graph_argument_or_print(*args);
  if (!graph) return exit_invalid;
  World worlds[2];
  try {
    worlds[0] = default_world();
    const auto scene = args->value("--scene");
    worlds[1] =
        scene ? load_world(*scene, renderer_world_options(*scene, args->values("--asset-root"))) : default_world();
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid;
  }

  // The graph as a file of its own, rewritten with another name at each reload.
  const auto dir = std::filesystem::temp_directory_path() / ("lumagraph-soak-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string graph_path = (dir / "graph.json").string();
  const std::string base_name = graph->name;
  auto write_graph = [&](uint64_t reloads) {
    graph->name = base_name + "-" + std::to_string(reloads);
    if (!write_file_atomically(graph_path, graph_to_text(*graph), &error))
      throw std::runtime_error("cannot write the reloaded graph: " + error);
  };

  std::FILE* csv = std::fopen(csv_path.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "lumagraph soak: cannot write %s\n", csv_path.c_str());
    return exit_failed;
  }
  std::fprintf(csv, "frame,resident_mib,device_mib,gpu_ms,reloaded,world_changed,heap_in_use_mib,heap_held_mib\n");
  size_t validation_messages = 0, non_finite = 0;
  Peak warm, after;
  int status = exit_ok;
  try {
    RendererOptions options;
    options.device.validation = args->has("--validate");
    options.asset_roots.roots = args->values("--asset-root");
    Renderer renderer(options);
    uint64_t reloads = 0, world = 0;
    write_graph(reloads);
    renderer.load_graph(graph_path);
    for (uint64_t f = 0; f < frames; ++f) {
      const bool reload = reload_every > 0 && f > 0 && f % reload_every == 0;
      const bool change_world = world_every > 0 && f > 0 && f % world_every == 0;
      if (reload) {
        write_graph(++reloads);
        renderer.reload_graph();
      }
      if (change_world) {
        world ^= 1;
        if (!args->value("--scene")) worlds[world] = default_world();  // fresh assets: uploaded again
      }
      const FrameStats& stats = renderer.render(worlds[world], size);
      non_finite += non_finite_values(renderer.read_output());
      print_validation("soak", renderer.context(), validation_messages);
      const double resident = double(resident_bytes()) / (1 << 20);
      const double device = double(renderer.context().device_memory_used()) / (1 << 20);
      (f < warmup ? warm : after).add(resident, device);
      const HeapBytes heap = heap_bytes();
      std::fprintf(csv, "%llu,%.3f,%.3f,%.3f,%d,%d,%.3f,%.3f\n", (unsigned long long)f, resident, device,
                   stats.gpu_ms, reload ? 1 : 0, change_world ? 1 : 0, heap.in_use_mib, heap.held_mib);
      if (isatty(STDERR_FILENO) && f % 50 == 0)
        std::fprintf(stderr, "\rframe %llu/%llu  resident %.1f MiB  device %.1f MiB", (unsigned long long)f,
                     (unsigned long long)frames, resident, device);
    }
    if (isatty(STDERR_FILENO)) std::fputc('\n', stderr);
  } catch (const GraphError& e) {
    std::fputs(e.what(), stderr);
    status = exit_invalid;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lumagraph soak: error: %s\n", e.what());
    status = exit_failed;
  }
  std::fclose(csv);
  std::filesystem::remove_all(dir);
  if (status != exit_ok) return status;

  const double resident_growth = growth(after.resident, warm.resident);
  const double device_growth = growth(after.device, warm.device);
  std::printf(
      "%llu frames at %ux%u: peak resident %.1f MiB in the warm-up, %.1f after (%+.2f%%); "
      "peak device %.1f MiB, %.1f after (%+.2f%%); %zu non-finite values; %zu validation messages\n"
      "wrote %s\n",
      (unsigned long long)frames, size.width, size.height, warm.resident, after.resident, 100 * resident_growth,
      warm.device, after.device, 100 * device_growth, non_finite, validation_messages, csv_path.c_str());
  const bool flat = resident_growth < 0.01 && device_growth < 0.01;
  if (!flat) std::fprintf(stderr, "lumagraph soak: memory grew by more than 1%% after the warm-up\n");
  return flat && non_finite == 0 && validation_messages == 0 ? exit_ok : exit_failed;
}

}  // namespace lg::cli
