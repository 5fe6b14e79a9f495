// Specialization and culling on the real node schemas: each skipped node or pass is in the
// plan with the reason a user reads.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/plan_checks/plan_fixtures.h"

namespace lg::test {
namespace {

const PlanNode& node(const Plan& plan, const std::string& id) {
  auto it = std::find_if(plan.nodes.begin(), plan.nodes.end(), [&](const PlanNode& n) { return n.id == id; });
  if (it == plan.nodes.end()) throw std::runtime_error("no node " + id);
  return *it;
}

int pass_position(const Plan& plan, const std::string& name) {
  for (size_t p = 0; p < plan.passes.size(); ++p)
    if (plan.passes[p].name == name) return static_cast<int>(p);
  return -1;
}

Plan compile_example(const std::string& file, const std::string& scene, const Graph* graph = nullptr) {
  CompileOptions options;
  options.scene = load_scene(scene);
  return compile_or_throw(graph ? *graph : load_example(file), builtin_registry(), options);
}

TEST(PlanSpecialization, NoAreaLightsDropsTheAreaPass) {
  Plan plan = compile_example("examples/default.json", "examples/scenes/sun-only.json");
  const PlanNode& light = node(plan, "light");
  EXPECT_EQ(light.state, NodeState::Kind::active);
  ASSERT_EQ(light.dropped.size(), 1u);
  EXPECT_EQ(light.dropped[0].first, "area");
  EXPECT_EQ(light.dropped[0].second, "the scene has no area lights");
  EXPECT_EQ(pass_position(plan, "light/area"), -1);
  EXPECT_GE(pass_position(plan, "light/direct"), 0);
  // With area lights the pass is there.
  EXPECT_GE(pass_position(compile_example("examples/default.json", ""), "light/area"), 0);
}

TEST(PlanSpecialization, PinholeCameraBypassesDepthOfField) {
  Plan plan = compile_example("examples/post.json", "examples/scenes/default.json");
  const PlanNode& dof = node(plan, "dof");
  EXPECT_EQ(dof.state, NodeState::Kind::bypassed);
  EXPECT_EQ(dof.reason, "the camera is a pinhole (aperture 0): nothing is out of focus");
  EXPECT_EQ(pass_position(plan, "dof/gather"), -1);
  // Bloom reads what dof would have read: the image-based lighting result.
  int downsample = pass_position(plan, "bloom/downsample");
  ASSERT_GE(downsample, 0);
  bool reads_ibl = false;
  for (const auto& a : plan.passes[downsample].accesses) reads_ibl |= plan.resources[a.resource].desc.name == "ibl.color";
  EXPECT_TRUE(reads_ibl);
}

TEST(PlanSpecialization, ThinLensKeepsDepthOfField) {
  Plan plan = compile_example("examples/post.json", "examples/scenes/thin-lens.json");
  EXPECT_EQ(node(plan, "dof").state, NodeState::Kind::active);
  EXPECT_LT(pass_position(plan, "dof/coc"), pass_position(plan, "dof/gather"));
  EXPECT_LT(pass_position(plan, "dof/composite"), pass_position(plan, "bloom/downsample"));
}

TEST(PlanSpecialization, BloomWithZeroIntensityIsBypassed) {
  Graph graph = load_example("examples/post.json");
  for (auto& n : graph.nodes)
    if (n.id == "bloom") n.params.set("intensity", 0);
  Plan plan = compile_example("", "", &graph);
  EXPECT_EQ(node(plan, "bloom").state, NodeState::Kind::bypassed);
  EXPECT_EQ(node(plan, "bloom").reason, "intensity is 0: bloom would add nothing");
  EXPECT_EQ(pass_position(plan, "bloom/upsample"), -1);
}

TEST(PlanSpecialization, NoShadowCastersDropsShadowsAndNothingReadsTheShadowMap) {
  Graph graph = load_example("examples/minimal.json");
  SceneSummary scene;
  scene.shadows = false;
  CompileOptions options;
  options.scene = scene;
  Plan plan = compile_or_throw(graph, builtin_registry(), options);
  EXPECT_EQ(pass_position(plan, "light/shadows"), -1);
  for (const auto& pass : plan.passes)
    for (const auto& a : pass.accesses) EXPECT_NE(plan.resources[a.resource].desc.name, "light/shadow_map") << pass.name;
}

TEST(PlanCulling, UnusedNodeIsCulledWithItsReason) {
  Graph graph = load_example("examples/minimal.json");
  GraphNode extra;
  extra.id = "spare";
  extra.type = "occlusion.ssao";
  graph.nodes.push_back(extra);
  graph.links.push_back({{"gbuf", "gbuffer"}, {"spare", "gbuffer"}, {}, {}});
  Plan plan = compile_example("", "", &graph);
  EXPECT_EQ(node(plan, "spare").state, NodeState::Kind::culled);
  EXPECT_EQ(node(plan, "spare").reason, "no output depends on it");
  EXPECT_EQ(pass_position(plan, "spare/sample"), -1);
}

TEST(PlanCulling, NodeFeedingOnlyABypassedNodeNamesIt) {
  // A second G-buffer feeds only dof's depth input; with a pinhole camera dof is bypassed.
  Graph graph = load_example("examples/post.json");
  GraphNode depth;
  depth.id = "dof_depth";
  depth.type = "scene.gbuffer";
  graph.nodes.push_back(depth);
  for (auto& l : graph.links)
    if (l.to.node == "dof" && l.to.port == "gbuffer") l.from = {"dof_depth", "gbuffer"};
  Plan plan = compile_example("", "", &graph);
  EXPECT_EQ(node(plan, "dof_depth").state, NodeState::Kind::culled);
  EXPECT_EQ(node(plan, "dof_depth").reason, "only 'dof' uses it, and that node is bypassed");
}

TEST(PlanOrder, ExamplesRunProducersBeforeConsumersAndStaticPassesFirst) {
  for (const auto& file : example_files())
    for (const auto& scene : scene_files()) {
      Plan plan = compile_example(file, scene);
      bool dynamic_seen = false;
      for (const auto& pass : plan.passes) {
        EXPECT_FALSE(pass.is_static && dynamic_seen) << file << ": static pass " << pass.name << " after a dynamic one";
        dynamic_seen |= !pass.is_static;
      }
      EXPECT_LT(pass_position(plan, "gbuf/raster"), pass_position(plan, "light/direct")) << file;
      EXPECT_LT(pass_position(plan, "light/direct"), pass_position(plan, "tonemap/map")) << file;
      for (const auto& n : plan.nodes)
        EXPECT_NE(n.state, NodeState::Kind::culled) << file << ": " << n.id << " culled: " << n.reason;
      // Every resource is written before it is read within the frame (history copies and
      // cached results come from earlier frames).
      std::vector<bool> written(plan.resources.size());
      for (const auto& pass : plan.passes)
        for (const auto& a : pass.accesses) {
          const auto& r = plan.resources[a.resource].desc;
          if (usage_reads(a.usage) && !usage_writes(a.usage) && r.history_of < 0)
            EXPECT_TRUE(written[a.resource]) << file << ": " << pass.name << " reads " << r.name << " before it is written";
          if (usage_writes(a.usage)) written[a.resource] = true;
        }
    }
}

TEST(PlanHistory, TemporalLoopGetsAPreviousFrameCopy) {
  Plan plan = compile_example("examples/default.json", "");
  auto find = [&](const std::string& name) {
    for (size_t r = 0; r < plan.resources.size(); ++r)
      if (plan.resources[r].desc.name == name) return static_cast<int>(r);
    return -1;
  };
  int current = find("gtao.ao"), previous = find("gtao.ao@previous");
  ASSERT_GE(current, 0);
  ASSERT_GE(previous, 0);
  EXPECT_EQ(plan.resources[previous].desc.history_of, current);
  EXPECT_EQ(plan.resources[current].desc.lifetime, ResourceLifetime::history);
  EXPECT_EQ(plan.resources[previous].placement.block, 1);
  EXPECT_EQ(plan.resources[current].placement.block, 1);
  bool history_barrier = false;
  for (const auto& b : plan.barriers) history_barrier |= b.reason == BarrierReason::history;
  EXPECT_TRUE(history_barrier);
}

TEST(PlanSizes, ResourcesFollowTheFrameAndTheirRules) {
  CompileOptions options;
  options.frame = {1000, 600};
  Graph graph = load_example("examples/post.json");
  for (auto& n : graph.nodes)
    if (n.id == "gbuf") n.params.set("resolution_scale", 0.5);
  Plan plan = compile_or_throw(graph, builtin_registry(), options);
  auto res = [&](const std::string& name) -> const LoweredResource& {
    for (const auto& r : plan.resources)
      if (r.desc.name == name) return r.desc;
    throw std::runtime_error("no resource " + name);
  };
  EXPECT_EQ(res("gbuf.gbuffer.depth").width, 500u);
  EXPECT_EQ(res("gbuf.gbuffer.depth").height, 300u);
  EXPECT_EQ(res("ibl.color").width, 500u);           // extent input:gbuffer
  EXPECT_EQ(res("bloom/chain").width, 250u);         // half of its input
  EXPECT_EQ(res("bloom/chain").mips, 6u);            // levels
  EXPECT_EQ(res("sky.cube").layers, 6u);             // a cube
  EXPECT_EQ(res("sky.cube").mips, 8u);               // full chain of 128
  EXPECT_EQ(res("sh.sh").width, 9u);                 // (order + 1)^2 coefficients
  EXPECT_EQ(res("sh.sh").bytes, 9u * 16);            // one vec4 each
  EXPECT_EQ(res("gbuf.gbuffer.depth").bytes, 500u * 300 * 4);
  // A full mip chain of a 128 cube in rgba16f: 6 faces x sum of 4^-k x 128^2 x 8 bytes.
  uint64_t texels = 0;
  for (uint32_t m = 0; m < 8; ++m) texels += uint64_t{128u >> m} * (128u >> m);
  EXPECT_EQ(res("sky.cube").bytes, texels * 6 * 8);
}

}  // namespace
}  // namespace lg::test
