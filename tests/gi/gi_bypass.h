// When gi.lpv and gi.voxel are bypassed: an example graph that links the node into lighting.ibl,
// compiled against a scene summary, with or without the node's `sh` input linked. A bypassed
// node has its reason in the plan and none of its passes, and lighting.ibl stays (its
// irradiance_volume input unlinked); a kept node has its three passes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "graph/compiler.h"
#include "graph/graph_io.h"
#include "nodes/builtin_schemas.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg::test {

// `example`: the graph file; `node`: the id of the node in it (its passes are named "node/...");
// `reason`: the plan's reason when bypassed, empty when the node must run.
inline void expect_gi_node(const std::string& example, const std::string& node, const SceneSummary& scene,
                           bool sh_linked, const std::string& reason) {
  Diagnostics d;
  std::optional<Graph> graph = load_graph_file(example, d);
  ASSERT_TRUE(graph) << d.to_string();
  if (!sh_linked) {
    ASSERT_TRUE(remove_link_to(*graph, node + ".sh"));
  }
  CompileOptions options;
  options.scene = scene;
  const CompileResult result = compile(*graph, builtin_registry(), options, d);
  ASSERT_TRUE(result.plan) << d.to_string();
  const auto found = std::find_if(result.plan->nodes.begin(), result.plan->nodes.end(),
                                  [&](const PlanNode& n) { return n.id == node; });
  ASSERT_NE(found, result.plan->nodes.end());
  const auto ibl = std::find_if(result.plan->nodes.begin(), result.plan->nodes.end(),
                                [](const PlanNode& n) { return n.id == "ibl"; });
  ASSERT_NE(ibl, result.plan->nodes.end());
  EXPECT_EQ(ibl->state, NodeState::Kind::active);
  const std::string prefix = node + "/";
  const auto passes = std::count_if(result.plan->passes.begin(), result.plan->passes.end(),
                                    [&](const PlanPass& p) { return p.name.rfind(prefix, 0) == 0; });
  if (reason.empty()) {
    EXPECT_EQ(found->state, NodeState::Kind::active) << found->reason;
    EXPECT_EQ(passes, 3);
  } else {
    EXPECT_EQ(found->state, NodeState::Kind::bypassed);
    EXPECT_EQ(found->reason, reason);
    EXPECT_EQ(passes, 0);
  }
}

// The default scene with no light of any kind (its environment kept).
inline SceneSummary scene_without_lights() {
  SceneSummary s = default_scene_summary();
  s.directional_lights = s.point_lights = s.spot_lights = 0;
  s.sphere_lights = s.tube_lights = s.rectangle_lights = 0;
  return s;
}

}  // namespace lg::test
