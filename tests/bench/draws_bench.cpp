// lumagraph-bench-draws: what per-draw work and frustum culling cost in the G-buffer pass on
// lavapipe. A generated scene of 300 spheres (about 250,000 triangles) drawn as one draw (all
// spheres merged into one mesh) or as 300 draws (a mesh each), with every sphere in view or half
// of them behind the camera, the 300 draws with scene.gbuffer's frustum culling on and off: the
// G-buffer pass's GPU time from the executor's timestamps (median, fastest and slowest of the
// frames after the first two, which compile pipelines and upload). Then the default graph on the default world, its
// whole frame's GPU and CPU time. The graph is scene.gbuffer into lighting.deferred with no light, so nothing else
// draws the scene. Writes draws.csv and draws_default_graph.csv (scripts/run-draws-benchmarks).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/bench/bench_flags.h"

namespace lg::bench {
namespace {

constexpr int kSpheres = 300, kColumns = 20;
constexpr int kSegments = 30, kRings = 14;  // 840 triangles a sphere, 252,000 in all

struct Options {
  std::string results_dir = "bench-results";
  FrameSize frame{1280, 720};
  int frames = 12;
};

struct Spread {
  double median = 0, min = 0, max = 0;
};

Spread spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  if (v.empty()) return {};
  const size_t n = v.size();
  return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

// Where sphere `i` stands: a 20 x 15 grid 8 m in front of the camera, which at 50 degrees and
// 16:9 holds it; with `half_behind`, the second half of the spheres stand behind the camera.
glm::vec3 sphere_position(int i, bool half_behind) {
  const float x = (float(i % kColumns) - 9.5f) * 0.45f, y = (float(i / kColumns) - 7.0f) * 0.45f;
  return {x, y, half_behind && i >= kSpheres / 2 ? 8.0f : -8.0f};
}

// The spheres as `draws` draws (1 or kSpheres), the same triangles either way.
World sphere_world(int draws, bool half_behind) {
  World world;
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  world.add(camera, Transform{.rotation = look_rotation({0.0f, 0.0f, -1.0f})});
  const MeshData sphere = make_sphere(0.2f, kSegments, kRings);
  if (draws == kSpheres) {
    const int mesh = world.add_mesh(sphere);
    for (int i = 0; i < kSpheres; ++i) {
      // A mesh each, as separate assets would be: every draw binds its own buffers.
      Entity e = world.create();
      world.add(e, MeshRenderer{i == 0 ? mesh : world.add_mesh(sphere), -1});
      world.add(e, Transform{.position = sphere_position(i, half_behind)});
    }
    return world;
  }
  MeshData merged;
  merged.name = "spheres";
  for (int i = 0; i < kSpheres; ++i) {
    const auto base = uint32_t(merged.positions.size());
    for (const glm::vec3& p : sphere.positions) merged.positions.push_back(p + sphere_position(i, half_behind));
    merged.normals.insert(merged.normals.end(), sphere.normals.begin(), sphere.normals.end());
    merged.uvs.insert(merged.uvs.end(), sphere.uvs.begin(), sphere.uvs.end());
    for (uint32_t index : sphere.indices) merged.indices.push_back(base + index);
  }
  Entity e = world.create();
  world.add(e, MeshRenderer{world.add_mesh(std::move(merged)), -1});
  world.add(e, Transform{});
  return world;
}

Graph graph_from(const std::string& text) {
  Diagnostics d("draws-bench.json");
  std::optional<Graph> graph = parse_graph_text(text, d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

std::string gbuffer_graph(bool culling) {
  return std::string(R"({ "format": "lumagraph/1", "nodes": [
    { "id": "gbuf", "type": "scene.gbuffer", "params": { "frustum_culling": )") +
         (culling ? "true" : "false") + R"( } }, { "id": "light", "type": "lighting.deferred" } ],
  "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" } ], "outputs": [ "light.color" ] })";
}

// Per timed frame (the first two left out), pass `pass`'s GPU time (none when empty), the whole
// frame's GPU time and the frame's CPU time.
struct Times {
  std::vector<double> pass_ms, frame_ms, cpu_ms;
};

Times run_frames(Renderer& renderer, const World& world, const Options& o, const std::string& pass) {
  Times t;
  for (int f = 0; f < o.frames + 2; ++f) {
    const FrameStats& stats = renderer.render(world, o.frame);
    if (f < 2) continue;
    for (const PassStats& p : stats.passes)
      if (p.name == pass) t.pass_ms.push_back(p.gpu_ms);
    t.frame_ms.push_back(stats.gpu_ms);
    t.cpu_ms.push_back(stats.cpu_ms);
  }
  return t;
}

int run(const Options& o) {
  std::filesystem::create_directories(o.results_dir);
  Renderer culled, unculled;
  culled.set_graph(graph_from(gbuffer_graph(true)));
  unculled.set_graph(graph_from(gbuffer_graph(false)));
  std::printf("G-buffer pass on lavapipe, %ux%u, %d spheres of %d triangles, %d timed frames each\n", o.frame.width,
              o.frame.height, kSpheres, 2 * kSegments * kRings, o.frames);
  std::printf("%-6s %-12s %-8s %10s %9s %9s %9s\n", "draws", "placement", "culling", "submitted", "median", "fastest",
              "slowest");
  std::ofstream csv(o.results_dir + "/draws.csv");
  csv << "draws,placement,culling,triangles,submitted_triangles,frames,gbuffer_median_ms,gbuffer_min_ms,"
         "gbuffer_max_ms,frame_median_ms\n";
  struct Point {
    int draws;
    bool culling;
  };
  for (bool half_behind : {false, true})
    for (const Point p : {Point{1, true}, Point{kSpheres, false}, Point{kSpheres, true}}) {
      const World world = sphere_world(p.draws, half_behind);
      size_t triangles = 0;
      for (const auto& mesh : world.meshes()) triangles += mesh->indices.size() / 3;
      const Times t = run_frames(p.culling ? culled : unculled, world, o, "gbuf/raster");
      const Spread g = spread(t.pass_ms), f = spread(t.frame_ms);
      const char* placement = half_behind ? "half_behind" : "all_in_view";
      // Culling leaves out the spheres behind the camera when each is its own draw; one draw
      // of them all is always in view.
      const size_t submitted = p.draws == kSpheres && half_behind && p.culling ? triangles / 2 : triangles;
      std::printf("%-6d %-12s %-8s %10zu %9.2f %9.2f %9.2f\n", p.draws, placement, p.culling ? "on" : "off", submitted,
                  g.median, g.min, g.max);
      std::fflush(stdout);
      csv << p.draws << ',' << placement << ',' << (p.culling ? "on" : "off") << ',' << triangles << ',' << submitted
          << ',' << t.pass_ms.size() << ',' << g.median << ',' << g.min << ',' << g.max << ',' << f.median << '\n';
    }

  Renderer full;
  full.load_graph(LUMAGRAPH_SOURCE_DIR "/examples/default.json");
  const Times t = run_frames(full, default_world(), o, "");
  const Spread gpu = spread(t.frame_ms), cpu = spread(t.cpu_ms);
  std::printf(
      "\ndefault graph, default world, %ux%u, %d timed frames: GPU %.2f ms (%.2f to %.2f), CPU %.2f ms "
      "(%.2f to %.2f)\n",
      o.frame.width, o.frame.height, o.frames, gpu.median, gpu.min, gpu.max, cpu.median, cpu.min, cpu.max);
  std::ofstream(o.results_dir + "/draws_default_graph.csv")
      << "frames,gpu_median_ms,gpu_min_ms,gpu_max_ms,cpu_median_ms,cpu_min_ms,cpu_max_ms\n"
      << t.frame_ms.size() << ',' << gpu.median << ',' << gpu.min << ',' << gpu.max << ',' << cpu.median << ','
      << cpu.min << ',' << cpu.max << '\n';
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-draws [--results-dir DIR] [--frames N] [--size WxH]\n"
      "  defaults: bench-results, 12 timed frames (after 2 untimed), 1280x720\n");
  flags.text("--results-dir", o.results_dir);
  flags.count("--frames", o.frames);
  flags.size("--size", o.frame.width, o.frame.height);
  if (const auto status = flags.parse(argc, argv)) return *status;
  return lg::bench::run(o);
}
