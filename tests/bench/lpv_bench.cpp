// lumagraph-bench-lpv: the nodes that carry one bounce of the main directional light, gi.lpv and
// gi.voxel, against the path-traced reference on the Cornell box, the two rooms
// with a skylight (examples/worlds/two-rooms-sun.json: the two-room world of the probe benchmark
// with the sun coming through a hole in the west room's ceiling, its lamp left out, so the east
// room gets no light at all) and the gallery. Both carry one bounce of the main directional
// light, so the reference is traced with that light alone (no environment, no other lights) and
// two bounces (the visible surface and one more). Per world, for gi.lpv at four grids (8, 16, 32
// and 64 cells along the longest side, 8 iterations each, the lookup at its default resolution
// scale 1/4; the default grid 16 with 16 iterations, without propagation, whose time is that of
// everything but the propagation, and with the lookup at 1/2; --lpv picks others), for gi.voxel
// at three resolutions (32, 64 and 128 voxels along the longest side, six cones, resolution scale
// 0.5; and 64 at scale 1/4) and for "no indirect light": the relative RMS of the node's
// irradiance against the reference's (the RMS of the differences over the reference's mean,
// lumagraph-bench-probes' relative_rms; through tests/gi/prt_comparison.h), the reference's noise
// in the same measure, and the node's GPU time per frame at --frame-size (all its passes;
// lavapipe; the median and the least of the frames after the first, and each pass's median;
// both nodes keep their volume while nothing moves, so each is also timed with the sun turning). In
// the two rooms also the leak: the mean irradiance on the east room's floor over the west room's,
// a camera in each room (the reference's is 0). Writes lpv_points.csv (columns compatible with
// docs/bench/probes/probe_points.csv; for gi.voxel `grid` is the resolution and `iterations` the
// number of cones; mean_ratio the node's mean irradiance over the reference's, 1 unbiased;
// frame_ms_moving the median with the sun turning, see frame_ms; cpu_ms the CPU time the
// node adds to a frame, the process's over the G-buffer alone's) into --results-dir; --methods
// lpv or voxel runs one of them, --worlds some of the worlds; scripts/run-lpv-benchmarks plots
// it. Per row it also prints the mean ratio per way the surfaces face (docs/lpv.md, "Energy and
// direction").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "nodes/gi/common/main_light.h"
#include "nodes/gi/path_tracer/path_tracer.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/renderer_pass_timing.h"
#include "tests/bench/two_rooms_leak.h"
#include "tests/gi/prt_comparison.h"

namespace lg::bench {
namespace {

namespace fs = std::filesystem;

// gi.lpv's and gi.voxel's default resolution_scale (their schema.json), as 1 / this.
constexpr int kLpvDefaultDivisor = 4;
constexpr int kVoxelDefaultDivisor = 4;

// The resolution_scale each node has by default, as 1 / this.
int default_divisor(const std::string& method) {
  return method == "lpv" ? kLpvDefaultDivisor : kVoxelDefaultDivisor;
}

// One setting of one node: gi.lpv's grid and iterations, or gi.voxel's resolution (and its six
// cones, fixed), and its resolution_scale.
struct Quality {
  std::string method;  // the node's id in the graph, and its passes' prefix
  int grid, iterations;
  int scale_divisor;  // the node's resolution_scale is 1 / this
};

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 160, height = 90;                // against the reference
  uint32_t frame_width = 1280, frame_height = 720;  // timed
  uint32_t spp = 256, frames = 4;
  std::string methods = "lpv,voxel";
  std::string worlds = "cornell-box,two-rooms-sun,gallery";
  // gi.lpv's settings (iterations 0: without propagation); main() parses --lpv.
  std::vector<Quality> lpv = {{"lpv", 8, 8, kLpvDefaultDivisor},
                              {"lpv", 16, 8, kLpvDefaultDivisor},
                              {"lpv", 32, 8, kLpvDefaultDivisor},
                              {"lpv", 64, 8, kLpvDefaultDivisor},
                              {"lpv", 16, 16, kLpvDefaultDivisor},
                              {"lpv", 16, 0, kLpvDefaultDivisor},
                              {"lpv", 16, 8, 2}};
};

// gi.lpv's grid and iterations ("32/8"); gi.voxel's resolution; either's resolution_scale where it
// is not the node's default ("64 1/4").
std::string quality_name(const Quality& q) {
  const std::string name =
      q.method == "lpv" ? std::to_string(q.grid) + "/" + std::to_string(q.iterations) : std::to_string(q.grid);
  return name + (q.scale_divisor == default_divisor(q.method) ? "" : " 1/" + std::to_string(q.scale_divisor));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Graph node_graph(const Quality& q) {
  const std::string params =
      (q.method == "lpv" ? R"("gi.lpv", "params": { "grid": )" + std::to_string(q.grid) + R"(, "iterations": )" +
                               std::to_string(q.iterations)
                         : R"("gi.voxel", "params": { "resolution": )" + std::to_string(q.grid)) +
      R"(, "resolution_scale": )" + std::to_string(1.0 / q.scale_divisor);
  Diagnostics d(q.method + "-bench.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": ")" + q.method + R"(", "type": )" + params +
                                                    R"( } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": ")" + q.method +
                                                    R"(.gbuffer" } ],
    "outputs": [ ")" + q.method + R"(.irradiance" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

struct FrameTime {
  double median_ms, min_ms;
  double moving_median_ms = NAN;  // with the sun turning every frame (the volume rebuilt)
  double cpu_ms = NAN;            // the process's CPU time a frame, all threads (the frame's, not the node's)
};

// The G-buffer alone, whose CPU time a frame run() takes from each node's frame.
Graph gbuffer_graph() {
  Diagnostics d("gbuffer-bench.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" } ], "links": [], "outputs": [ "gbuf.gbuffer" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

// The process's CPU time a frame (all threads: lavapipe's GPU work is CPU work) over the frames
// after the first of `graph`.
double frame_cpu_ms(const World& world, Graph graph, const Options& o) {
  Renderer renderer;
  renderer.set_graph(std::move(graph));
  renderer.render(world, {o.frame_width, o.frame_height});
  const double start = process_cpu_ms();
  for (uint32_t f = 0; f < o.frames; ++f) renderer.render(world, {o.frame_width, o.frame_height});
  return (process_cpu_ms() - start) / o.frames;
}

// The node's passes' GPU time over the frames after the first (pipelines JIT-compiled): the
// median, and the least, which on a machine shared with other work is the nearest to its cost
// alone; each pass's median is printed. Both nodes keep their volume (gi.lpv its sum, since stop
// 36) while the scene stands still, so each is also timed with the sun turning 0.1 degrees a
// frame (everything rebuilt every frame).
FrameTime frame_ms(const World& world, const Quality& q, const Options& o) {
  if (o.frames == 0) return {NAN, NAN};  // --frames 0: accuracy only
  const std::string prefix = q.method + "/";
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  // The sorted frame times; prints each pass's median.
  auto timed = [&](bool turning, const char* label) {
    World scene = world;
    Renderer renderer;
    renderer.set_graph(node_graph(q));
    std::vector<double> frames;
    std::map<std::string, std::vector<double>> passes;
    double cpu_start = 0;
    for (uint32_t f = 0; f <= o.frames; ++f) {
      if (f == 1) cpu_start = process_cpu_ms();
      if (turning)
        scene.each<DirectionalLight, Transform>([](Entity, DirectionalLight&, Transform& t) {
          t.rotation = glm::angleAxis(glm::radians(0.1f), glm::vec3(0, 1, 0)) * t.rotation;
        });
      const FrameStats& stats = renderer.render(scene, {o.frame_width, o.frame_height});
      if (f == 0) continue;
      double ms = 0;
      for (const PassStats& p : stats.passes)
        if (p.name.starts_with(prefix)) ms += p.gpu_ms, passes[p.name].push_back(p.gpu_ms);
      frames.push_back(ms);
    }
    std::printf("  %s %s%s: %.1f ms a frame:", q.method.c_str(), quality_name(q).c_str(), label, median(frames));
    for (const auto& [name, ms] : passes) std::printf(" %s %.1f", name.c_str(), median(ms));
    std::printf(" ms (medians)\n");
    std::sort(frames.begin(), frames.end());
    return std::pair(frames, (process_cpu_ms() - cpu_start) / o.frames);
  };
  const auto [still, cpu_ms] = timed(false, "");
  FrameTime out{still[still.size() / 2], still.front()};
  out.cpu_ms = cpu_ms;
  out.moving_median_ms = median(timed(true, ", sun turning").first);
  return out;
}

// The leak in the two rooms (two_rooms_leak.h) with the node's irradiance.
double leak_ratio(const World& world, const Quality& q, const Options& o) {
  const RoomFloors floors = two_rooms_floors(world, o.width, o.height, [&](const World& room) {
    Renderer renderer;
    renderer.set_graph(node_graph(q));
    renderer.render(room, {o.width, o.height});
    return renderer.executor().read_image(q.method + ".irradiance");
  });
  // Both are small where little light bounces onto the floors: the ratio alone can mislead.
  std::printf("  %s %s: mean irradiance on the east room's floor %.5f, the west room's %.5f W/m^2\n", q.method.c_str(),
              quality_name(q).c_str(), floors.east, floors.west);
  return floors.leak();
}

int run(const Options& o) {
  const fs::path dir = fs::absolute(o.results_dir);
  fs::create_directories(dir);
  std::ofstream csv(dir / "lpv_points.csv");
  csv << "world,method,quality,grid,iterations,frame_ms,relative_rms,reference_noise,beyond_noise,leak,frame_ms_min,"
         "mean_ratio,frame_ms_moving,cpu_ms\n";
  std::printf("%-13s %-6s %-8s %9s %8s %8s %9s %8s %8s %6s\n", "world", "method", "quality", "frame ms", "min ms",
              "rel RMS", "ref noise", "beyond", "leak", "scale");
  std::vector<Quality> qualities;
  if (o.methods.find("lpv") != std::string::npos) qualities = o.lpv;
  if (o.methods.find("voxel") != std::string::npos)
    qualities.insert(qualities.end(),
                     {{"voxel", 32, 6, kVoxelDefaultDivisor},
                      {"voxel", 64, 6, kVoxelDefaultDivisor},
                      {"voxel", 128, 6, kVoxelDefaultDivisor},
                      {"voxel", 64, 6, 2}});
  for (const std::string& name : split_commas(o.worlds)) {
    const World world = load_world(std::string(LUMAGRAPH_SOURCE_DIR) + "/examples/worlds/" + name + ".json");
    SceneView view = make_scene_view(world, float(o.width) / o.height);
    view.point_lights.clear(), view.spot_lights.clear(), view.sphere_lights.clear();
    view.tube_lights.clear(), view.rect_lights.clear();
    const int light = main_directional_light(view);  // the one light the nodes carry
    if (light >= 0) view.directional_lights = {view.directional_lights[size_t(light)]};
    const PathScene scene(view, PathEnvironment::none());
    PathTracerOptions ro;
    ro.width = o.width, ro.height = o.height, ro.samples_per_pixel = o.spp, ro.max_bounces = 2;
    const auto start = std::chrono::steady_clock::now();
    const ReferenceImage reference = trace_reference(scene, ro);
    std::printf("%s: reference %ux%u, %u paths, 2 bounces in %.1f s\n", name.c_str(), o.width, o.height, o.spp,
                seconds_since(start));
    const bool rooms = name == "two-rooms-sun";
    const double gbuffer_cpu_ms = o.frames ? frame_cpu_ms(world, gbuffer_graph(), o) : NAN;
    auto row = [&](const char* method, const std::string& quality, const Quality& q, FrameTime ms,
                   const test::PrtComparison& c, double leak) {
      const double beyond =
          std::sqrt(std::max(0.0, c.rms_over_mean * c.rms_over_mean - c.noise_over_mean * c.noise_over_mean));
      const std::string leak_text = rooms && std::isfinite(leak) ? std::to_string(leak) : "";
      std::printf("%-13s %-6s %-8s %9.2f %8.2f %8.4f %9.4f %8.4f %8s %6.3f\n", name.c_str(), method, quality.c_str(),
                  ms.median_ms, ms.min_ms, c.rms_over_mean, c.noise_over_mean, beyond, leak_text.c_str(), c.mean_ratio);
      const auto& f = c.mean_ratio_by_facing;
      std::printf("  scale by facing: +x %.3f -x %.3f +y %.3f -y %.3f +z %.3f -z %.3f\n", f[0], f[1], f[2], f[3], f[4],
                  f[5]);
      csv << name << ',' << method << ',' << quality << ',' << q.grid << ',' << q.iterations << ',' << ms.median_ms
          << ',' << c.rms_over_mean << ',' << c.noise_over_mean << ',' << beyond << ',' << leak_text << ',' << ms.min_ms
          << ',' << c.mean_ratio << ',';
      if (std::isfinite(ms.moving_median_ms)) csv << ms.moving_median_ms;
      csv << ',';
      // The CPU time the node adds to a frame: on 2 idle cores its passes take about half of it.
      const double cpu = ms.cpu_ms - gbuffer_cpu_ms;
      if (std::isfinite(cpu)) csv << cpu, std::printf("  CPU time it adds to a frame: %.1f ms\n", cpu);
      csv << '\n';
    };
    std::vector<float> dark;
    for (const Quality& q : qualities) {
      Renderer renderer;
      renderer.set_graph(node_graph(q));
      renderer.render(world, {o.width, o.height});
      const std::vector<float> frame = renderer.executor().read_image(q.method + ".irradiance");
      if (dark.empty()) {  // no indirect light, on the pixels the node covers
        dark = frame;
        for (size_t i = 0; i < dark.size(); ++i)
          if (i % 4 != 3) dark[i] = 0.0f;
        row("none", "-", {"none", 0, 0, 1}, {0.0, 0.0}, test::compare_with_reference(scene, reference, dark),
            rooms ? 0.0 : NAN);
      }
      const std::string quality = quality_name(q);
      row(q.method.c_str(), quality, q, frame_ms(world, q, o), test::compare_with_reference(scene, reference, frame),
          rooms ? leak_ratio(world, q, o) : NAN);
    }
  }
  std::printf("wrote %s\n", (dir / "lpv_points.csv").c_str());
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-lpv [--results-dir DIR] [--size WxH] [--frame-size WxH] [--spp N] [--frames N]\n"
      "                           [--methods lpv,voxel] [--worlds cornell-box,two-rooms-sun,gallery]\n"
      "                           [--lpv GRID/ITERATIONS[:K],...]   (--frames 0: no timing; K: resolution scale "
      "1/K)\n");
  flags.text("--results-dir", o.results_dir);
  flags.size("--size", o.width, o.height);
  flags.size("--frame-size", o.frame_width, o.frame_height);
  flags.count("--spp", o.spp);
  flags.count("--frames", o.frames, 0);
  flags.text("--methods", o.methods);
  flags.text("--worlds", o.worlds);
  std::string lpv;
  flags.text("--lpv", lpv);
  if (const auto status = flags.parse(argc, argv)) return *status;
  if (!lg::bench::names_known("lumagraph-bench-lpv", "--methods", o.methods, {"lpv", "voxel"})) return 2;
  if (!lg::bench::example_worlds_exist("lumagraph-bench-lpv", LUMAGRAPH_SOURCE_DIR, o.worlds)) return 2;
  if (!lpv.empty()) {
    o.lpv.clear();
    for (const std::string& setting : lg::bench::split_commas(lpv)) {
      int grid = 0, iterations = -1, divisor = lg::bench::kLpvDefaultDivisor, used = 0;
      const int read = std::sscanf(setting.c_str(), "%d/%d%n:%d%n", &grid, &iterations, &used, &divisor, &used);
      if (read < 2 || used != int(setting.size()) || grid < 4 || grid > 64 || iterations < 0 || iterations > 64 ||
          divisor < 1 || divisor > 4) {
        std::fprintf(stderr,
                     "lumagraph-bench-lpv: --lpv: '%s' is not GRID/ITERATIONS[:K] (grid 4-64, iterations 0-64, "
                     "resolution scale 1/K, K 1-4)\n",
                     setting.c_str());
        return 2;
      }
      o.lpv.push_back({"lpv", grid, iterations, divisor});
    }
  }
  return lg::bench::run(o);
}
