// The graph that tests of direct lighting render: scene.gbuffer feeding lighting.deferred, whose
// color is the output (read back with executor().read_image("light.color")).
#pragma once

#include <stdexcept>
#include <string>

#include "graph/graph_io.h"

namespace lg::test {

// `light_params`: the lighting.deferred node's params as a JSON object.
inline Graph deferred_lighting_graph(const std::string& light_params = "{}") {
  Diagnostics d("deferred-lighting-test.json");
  std::optional<Graph> graph = parse_graph_text(R"({ "format": "lumagraph/1", "nodes": [
      { "id": "gbuf", "type": "scene.gbuffer" },
      { "id": "light", "type": "lighting.deferred", "params": )" +
                                                    light_params + R"( } ],
    "links": [ { "from": "gbuf.gbuffer", "to": "light.gbuffer" } ],
    "outputs": [ "light.color" ] })",
                                                d);
  if (!graph) throw std::runtime_error(d.to_string());
  return std::move(*graph);
}

}  // namespace lg::test
