#include "tests/bench/area_pass_timing.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/scene/default_world.h"
#include "tests/bench/renderer_pass_timing.h"

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
  const std::vector<double> times = sorted_pass_ms(renderer, world, width, height, frames,
                                                   [](const std::string& name) { return name.ends_with("/area"); });
  return times[times.size() / 2];
}

}  // namespace lg::bench
