// lumagraph-bench-frame: the default frame's time, pass by pass (issue 21's 250 ms): the graph
// examples/default.json (or --graph) on the default world, as `lumagraph render` draws them, for
// --frames frames after a first one (it JIT-compiles the pipelines). Prints each pass's median and
// fastest GPU time, the whole frame's, and the process's CPU time a frame, which a loaded machine
// disturbs far less than lavapipe's timestamps (they can land a pass's time on its neighbour).
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "runtime/scene/default_world.h"
#include "tests/bench/bench_flags.h"
#include "tests/bench/renderer_pass_timing.h"

namespace {

struct Options {
  std::string graph = LUMAGRAPH_SOURCE_DIR "/examples/default.json";
  uint32_t width = 1280, height = 720;
  uint32_t frames = 8;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int run(const Options& o) {
  lg::Renderer renderer;
  renderer.load_graph(o.graph);
  const lg::World world = lg::default_world();
  renderer.render(world, {o.width, o.height});
  std::vector<std::string> order;  // schedule order
  std::map<std::string, std::vector<double>> pass_ms;
  std::vector<double> frame_ms;
  const double cpu_start = lg::bench::process_cpu_ms();
  for (uint32_t f = 0; f < o.frames; ++f) {
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
  std::printf("process CPU a frame: %.1f ms over %u frames at %ux%u\n", cpu_per_frame, o.frames, o.width, o.height);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  lg::bench::BenchFlags flags(
      "usage: lumagraph-bench-frame [--graph FILE] [--size WxH] [--frames N]\n"
      "  per pass, the median and fastest GPU time over N frames (default 8) after the first, of\n"
      "  the graph (default examples/default.json) on the default world at WxH (default 1280x720)\n");
  flags.text("--graph", o.graph);
  flags.size("--size", o.width, o.height);
  flags.count("--frames", o.frames);
  if (auto status = flags.parse(argc, argv)) return *status;
  return run(o);
}
