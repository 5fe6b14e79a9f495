// The nodes that carry one bounce of the main directional light (gi.lpv, gi.voxel) on a scene
// without one: an example graph that links the node into lighting.ibl compiles with the node
// bypassed, the reason in the plan, none of its passes, and lighting.ibl kept (its
// irradiance_volume input unlinked); with a directional light, the node's three passes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"

namespace lg::test {

// `example`: the graph file; `node`: the id of the node in it (its passes are named "node/...").
inline void expect_dropped_without_a_directional_light(const std::string& example, const std::string& node) {
  Diagnostics d;
  std::optional<Graph> graph = load_graph_file(example, d);
  ASSERT_TRUE(graph) << d.to_string();
  CompileOptions options;
  options.scene = default_scene_summary();
  options.scene.directional_lights = 0;
  const CompileResult result = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(result.plan) << d.to_string();
  auto state_of = [&](const std::string& id) {
    for (const PlanNode& n : result.plan->nodes)
      if (n.id == id) return std::pair{n.state, n.reason};
    return std::pair{NodeState::Kind::culled, std::string("missing")};
  };
  EXPECT_EQ(state_of(node).first, NodeState::Kind::bypassed);
  EXPECT_EQ(state_of(node).second, "the scene has no directional lights");
  EXPECT_EQ(state_of("ibl").first, NodeState::Kind::active);
  const std::string prefix = node + "/";
  for (const PlanPass& p : result.plan->passes) EXPECT_NE(p.name.rfind(prefix, 0), 0u) << p.name;

  options.scene.directional_lights = 1;  // and with one, its three passes
  const CompileResult lit = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(lit.plan) << d.to_string();
  EXPECT_EQ(std::count_if(lit.plan->passes.begin(), lit.plan->passes.end(),
                          [&](const PlanPass& p) { return p.name.rfind(prefix, 0) == 0; }),
            3);
}

}  // namespace lg::test
