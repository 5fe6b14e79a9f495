// lumagraph-bench-frame: the default frame's time, pass by pass (issue 21's 250 ms): the graph
// examples/default.json (or --graph) on the default world, as `lumagraph render` draws them, for
// --frames frames after a first one (it JIT-compiles the pipelines). Prints each pass's median and
// fastest GPU time, the whole frame's, and the process's CPU time a frame, which a loaded machine
// disturbs far less than lavapipe's timestamps (they can land a pass's time on its neighbour).
// --world FILE draws a world file instead; --orbit DEGREES turns the camera about the vertical
// by +DEGREES and back in turn, so that no frame sees the last one's view (a moving camera: what
// a node keeps while the camera stands still, as gi.voxel's cones, is computed every frame).
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "api/world_loading.h"
#include "runtime/scene/components.h"
#include "runtime/scene/default_world.h"
#include "runtime/scene/load_world.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/renderer_pass_timing.h"

namespace {

struct Options {
  std::string graph = LUMAGRAPH_SOURCE_DIR "/examples/default.json";
  uint32_t width = 1280, height = 720;
  uint32_t frames = 8;
  bool area_lights = true;
  std::string world;    // empty: the default world
  double orbit = 0.0;   // degrees the camera turns each frame, back and forth
};

// The world without its sphere, tube and rect lights: light/area is most of the default frame,
// and without it the process's CPU time a frame is the other passes', so a change to one of them
// shows above a loaded machine's noise.
void remove_area_lights(lg::World& world) {
  std::vector<lg::Entity> lights;
  world.each<lg::SphereLight>([&](lg::Entity e, const lg::SphereLight&) { lights.push_back(e); });
  world.each<lg::TubeLight>([&](lg::Entity e, const lg::TubeLight&) { lights.push_back(e); });
  world.each<lg::RectLight>([&](lg::Entity e, const lg::RectLight&) { lights.push_back(e); });
  for (lg::Entity e : lights) {
    world.remove<lg::SphereLight>(e);
    world.remove<lg::TubeLight>(e);
    world.remove<lg::RectLight>(e);
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run(const Options& o) {
  lg::Renderer renderer;
  renderer.load_graph(o.graph);
  lg::World world = o.world.empty() ? lg::default_world() : lg::load_world(o.world, lg::renderer_world_options(o.world));
  if (!o.area_lights) remove_area_lights(world);
  renderer.render(world, {o.width, o.height});
  std::vector<std::string> order;  // schedule order
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<double> frame_ms;
  const double cpu_start = lg::bench::process_cpu_ms();
  for (uint32_t f = 0; f < o.frames; ++f) {
    if (o.orbit != 0.0) lg::bench::turn_cameras(world, f % 2 == 0 ? o.orbit : -o.orbit);
    const lg::FrameStats& stats = renderer.render(world, {o.width, o.height});
    frame_ms.push_back(stats.gpu_ms);
    for (const lg::PassStats& p : stats.passes) {
      if (p.cached) continue;
      if (!pass_ms.contains(p.name)) order.push_back(p.name);
      pass_ms[p.name].push_back(p.gpu_ms);
    }
  }
  const double cpu_per_frame = (lg::bench::process_cpu_ms() - cpu_start) / o.frames;
  std::printf("%-22s %10s %10s\n", "pass", "median ms", "fastest ms");
  for (const std::string& name : order) {
    const std::vector<double>& v = pass_ms[name];
    std::printf("%-22s %10.1f %10.1f\n", name.c_str(), median(v), *std::min_element(v.begin(), v.end()));
  }
  std::printf("%-22s %10.1f %10.1f\n", "frame (GPU)", median(frame_ms),
              *std::min_element(frame_ms.begin(), frame_ms.end()));
  std::printf("process CPU a frame: %.1f ms over %u frames at %ux%u%s\n", cpu_per_frame, o.frames, o.width, o.height,
              o.orbit != 0.0 ? ", the camera turning" : "");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-frame [--graph FILE] [--world FILE] [--size WxH] [--frames N] [--orbit DEGREES]\n"
      "                             [--no-area-lights]\n"
      "  per pass, the median and fastest GPU time over N frames (default 8) after the first, of\n"
      "  the graph (default examples/default.json) on the world (default: the default world) at WxH\n"
      "  (default 1280x720); --orbit turns the camera by +DEGREES and back in turn every frame;\n"
      "  --no-area-lights leaves out the world's sphere, tube and rect lights (and light/area)\n");
  flags.text("--graph", o.graph);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  flags.text("--world", o.world);
  std::vector<double> orbit;
  flags.numbers("--orbit", orbit);
  flags.set_switch("--no-area-lights", o.area_lights, false);
  if (auto status = flags.parse(argc, argv)) return *status;
  if (!orbit.empty()) o.orbit = orbit.front();
  return run(o);
}
