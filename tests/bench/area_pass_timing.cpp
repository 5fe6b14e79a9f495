#include "tests/bench/area_pass_timing.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/default_world.h"

namespace lg::bench {

double area_pass_ms(const std::string& area_specular, uint32_t width, uint32_t height, uint32_t frames) {
  const std::string path = LUMAGRAPH_SOURCE_DIR "/examples/default.json";
  Diagnostics d(path);
  std::optional<Graph> graph = load_graph_file(path, d);
  if (!graph) throw std::runtime_error(d.to_string());
  for (GraphNode& node : graph->nodes)
    if (node.type == "lighting.deferred") node.params.set("area_specular", JsonValue(area_specular));
  const World world = default_world();
  Renderer renderer;
  renderer.set_graph(std::move(*graph));
  std::vector<double> times;
  for (uint32_t f = 0; f <= frames; ++f) {
    const FrameStats& stats = renderer.render(world, {width, height});
    double ms = 0;
    for (const PassStats& p : stats.passes)
      if (p.name.size() > 5 && p.name.compare(p.name.size() - 5, 5, "/area") == 0) ms += p.gpu_ms;
    if (f > 0) times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace lg::bench
