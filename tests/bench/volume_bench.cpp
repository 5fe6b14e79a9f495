// lumagraph-bench-volume: gi.irradiance_volume's lookup pass on the device (lavapipe unless
// VK_ICD_FILENAMES says otherwise) at 1280x720 on the Cornell box (8 x 8 x 8 probes), for every
// representation with and without visibility: the pass's GPU time from the executor's
// timestamps, median of --frames frames after a first one (which bakes the probes and JIT-compiles
// the pipeline), and the in-graph bake's wall time (that first frame's CPU time). The issue's
// target is 30 ms for the lookup. Prints a table and writes volume_lookup.csv into --results-dir.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/load_world.h"

namespace lg::bench {
namespace {

struct Options {
  std::string results_dir = "bench-results";
  uint32_t width = 1280, height = 720;
  int frames = 10;
};

Graph lookup_graph(const std::string& representation, bool visibility) {
  Diagnostics d("volume-bench.json");
  std::optional<Graph> graph =
      parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "volume", "type": "gi.irradiance_volume",
        "params": { "representation": ")" +
                           representation + R"(", "visibility": )" + (visibility ? "true" : "false") + R"( } } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "volume.gbuffer" } ],
    "outputs": [ "volume.irradiance" ] })",
                       d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

int run(const Options& o) {
  const World world = load_world(LUMAGRAPH_SOURCE_DIR "/examples/worlds/cornell-box.json");
  std::filesystem::create_directories(o.results_dir);
  std::ofstream csv(std::filesystem::path(o.results_dir) / "volume_lookup.csv");
  csv << "representation,visibility,width,height,lookup_ms_median,lookup_ms_min,first_frame_cpu_ms\n";
  std::printf("gi.irradiance_volume lookup, Cornell box, %ux%u, median of %d frames\n", o.width, o.height, o.frames);
  std::printf("%-14s %-10s %12s %12s %16s\n", "form", "visibility", "median ms", "min ms", "bake+1st frame");
  for (const char* representation : {"sh_l1", "sh_l2", "ambient_cube", "octahedral"})
    for (bool visibility : {false, true}) {
      Renderer renderer;
      renderer.set_graph(lookup_graph(representation, visibility));
      const double first_cpu_ms = renderer.render(world, {o.width, o.height}).cpu_ms;
      std::vector<double> ms;
      for (int f = 0; f < o.frames; ++f)
        for (const PassStats& pass : renderer.render(world, {o.width, o.height}).passes)
          if (pass.name == "volume/lookup") ms.push_back(pass.gpu_ms);
      std::sort(ms.begin(), ms.end());
      const double median = ms.empty() ? 0.0 : ms[ms.size() / 2], least = ms.empty() ? 0.0 : ms.front();
      std::printf("%-14s %-10s %12.2f %12.2f %16.0f\n", representation, visibility ? "on" : "off", median, least,
                  first_cpu_ms);
      csv << representation << ',' << (visibility ? 1 : 0) << ',' << o.width << ',' << o.height << ',' << median << ','
          << least << ',' << first_cpu_ms << '\n';
    }
  return 0;
}

}  // namespace
}  // namespace lg::bench

int main(int argc, char** argv) {
  lg::bench::Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--results-dir")
      o.results_dir = value;
    else if (flag == "--size")
      std::sscanf(value.c_str(), "%ux%u", &o.width, &o.height);
    else if (flag == "--frames")
      o.frames = std::max(1, std::stoi(value));
    else {
      std::fprintf(stderr, "usage: lumagraph-bench-volume [--results-dir DIR] [--size WxH] [--frames N]\n");
      return 1;
    }
  }
  return lg::bench::run(o);
}
