// Phases 4 and 5, specialize and cull, alone: which nodes are bypassed or lose passes for a
// scene, which nodes nothing needs, and the reason each decision carries.
#include <gtest/gtest.h>

#include "graph/compiler/cull.h"
#include "graph/compiler/resolve.h"
#include "graph/compiler/specialize.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

// Resolves a graph (which must outlive the result) and runs specialize, then cull.
struct States {
  Graph graph;
  ResolvedGraph resolved;
  NodeStates specialized, culled;

  const NodeState& after_specialize(std::string_view id) const { return specialized[index(id)]; }
  const NodeState& after_cull(std::string_view id) const { return culled[index(id)]; }
  int index(std::string_view id) const {
    for (size_t n = 0; n < graph.nodes.size(); ++n)
      if (graph.nodes[n].id == id) return static_cast<int>(n);
    throw std::runtime_error("no node " + std::string(id));
  }
  std::string dropped(std::string_view id, std::string_view pass) const {
    int n = index(id);
    const NodeSchema& s = *resolved.nodes[n].schema;
    for (size_t p = 0; p < s.passes.size(); ++p)
      if (s.passes[p].name == pass) return std::string(specialized[n].why_dropped(p));
    throw std::runtime_error("no pass " + std::string(pass));
  }
};

std::unique_ptr<States> run(Graph g, const SceneSummary& scene, const Registry& registry = builtin_registry()) {
  auto s = std::make_unique<States>();
  s->graph = std::move(g);
  Diagnostics d;
  s->resolved = resolve(s->graph, registry, d);
  if (d.has_errors()) throw std::runtime_error(d.to_string());
  s->specialized = specialize(s->resolved, scene);
  s->culled = cull(s->resolved, s->specialized);
  return s;
}

using Kind = NodeState::Kind;

TEST(CompilerSpecialize, AreaLightPassIsDroppedOnlyWithoutAreaLights) {
  auto sun = run(test::load_example("examples/default.json"), test::load_scene("examples/scenes/sun-only.json"));
  EXPECT_EQ(sun->after_specialize("light").kind, Kind::active);
  EXPECT_EQ(sun->dropped("light", "area"), "the scene has no area lights");
  EXPECT_EQ(sun->dropped("light", "direct"), "");
  EXPECT_EQ(sun->dropped("light", "shadows"), "");  // the sun casts shadows

  auto room = run(test::load_example("examples/default.json"), default_scene_summary());
  EXPECT_EQ(room->dropped("light", "area"), "");

  // Any one kind of area light keeps the pass.
  SceneSummary rect = test::load_scene("examples/scenes/sun-only.json");
  rect.rectangle_lights = 1;
  EXPECT_EQ(run(test::load_example("examples/default.json"), rect)->dropped("light", "area"), "");
}

TEST(CompilerSpecialize, ShadowPassNeedsALightThatCastsShadows) {
  SceneSummary no_shadows = default_scene_summary();
  no_shadows.shadows = false;
  EXPECT_EQ(run(test::load_example("examples/minimal.json"), no_shadows)->dropped("light", "shadows"),
            "no light in the scene casts shadows");
  // Shadows on, but only area lights: nothing casts a shadow map either.
  SceneSummary area_only = default_scene_summary();
  area_only.directional_lights = 0;
  area_only.point_lights = 0;
  EXPECT_EQ(run(test::load_example("examples/minimal.json"), area_only)->dropped("light", "shadows"),
            "no light in the scene casts shadows");
}

TEST(CompilerSpecialize, DepthOfFieldIsBypassedForAPinholeCamera) {
  auto pinhole = run(test::load_example("examples/post.json"), default_scene_summary());
  const NodeState& dof = pinhole->after_specialize("dof");
  EXPECT_EQ(dof.kind, Kind::bypassed);
  EXPECT_EQ(dof.bypass_rule, 0);
  EXPECT_EQ(dof.reason, "the camera is a pinhole (aperture 0): nothing is out of focus");

  auto lens = run(test::load_example("examples/post.json"), test::load_scene("examples/scenes/thin-lens.json"));
  EXPECT_EQ(lens->after_specialize("dof").kind, Kind::active);
  EXPECT_EQ(lens->after_specialize("dof").reason, "");
}

TEST(CompilerSpecialize, BloomIsBypassedAtIntensityZeroOnly) {
  for (double intensity : {0.0, 1e-6, 0.04}) {
    Graph g = test::load_example("examples/post.json");
    test::node_named(g, "bloom").params.set("intensity", intensity);
    auto s = run(std::move(g), default_scene_summary());
    const NodeState& bloom = s->after_specialize("bloom");
    if (intensity == 0) {
      EXPECT_EQ(bloom.kind, Kind::bypassed);
      EXPECT_EQ(bloom.reason, "intensity is 0: bloom would add nothing");
    } else {
      EXPECT_EQ(bloom.kind, Kind::active) << intensity;
    }
  }
}

TEST(CompilerCull, ANodeNoOutputNeedsIsCulledWithItsReason) {
  Graph g = test::load_example("examples/minimal.json");
  test::add_node(g, "ssao", "occlusion.ssao");
  test::add_node(g, "ssao2", "occlusion.ssao");  // dead too: nothing live reads it
  test::add_link(g, "gbuf.gbuffer", "ssao.gbuffer");
  test::add_link(g, "gbuf.gbuffer", "ssao2.gbuffer");
  auto s = run(std::move(g), default_scene_summary());
  for (const char* id : {"ssao", "ssao2"}) {
    EXPECT_EQ(s->after_specialize(id).kind, Kind::active) << "specialize does not cull";
    EXPECT_EQ(s->after_cull(id).kind, Kind::culled) << id;
    EXPECT_EQ(s->after_cull(id).reason, "no output depends on it") << id;
  }
  for (const char* id : {"gbuf", "light", "tonemap", "out"}) EXPECT_EQ(s->after_cull(id).kind, Kind::active) << id;
}

TEST(CompilerCull, FileOutputsAreRootsToo) {
  // post.json asks for ibl.color besides the display: with the display removed, everything up
  // to ibl stays and what only the display needed goes.
  Graph g = test::load_example("examples/post.json");
  std::erase_if(g.nodes, [](const GraphNode& n) { return n.id == "out"; });
  test::remove_link_to(g, "out.color");
  auto s = run(std::move(g), test::load_scene("examples/scenes/thin-lens.json"));
  for (const char* id : {"gbuf", "sky", "sh", "specular", "dfg", "light", "ibl"})
    EXPECT_EQ(s->after_cull(id).kind, Kind::active) << id;
  for (const char* id : {"dof", "bloom", "tonemap"}) {
    EXPECT_EQ(s->after_cull(id).kind, Kind::culled) << id;
    EXPECT_EQ(s->after_cull(id).reason, "no output depends on it") << id;
  }
}

TEST(CompilerCull, ANodeThatOnlyFeedsABypassedNodeNamesIt) {
  // Without an environment, ibl forwards its direct light and needs none of the env nodes;
  // without BLEND materials, glass forwards ibl's colour and needs none either.
  SceneSummary dark = default_scene_summary();
  dark.environment = false;
  auto s = run(test::load_example("examples/default.json"), dark);
  EXPECT_EQ(s->after_cull("ibl").kind, Kind::bypassed);
  EXPECT_EQ(s->after_cull("ibl").reason, "the scene has no environment light");
  for (const char* id : {"sh", "specular", "dfg"}) {
    EXPECT_EQ(s->after_cull(id).kind, Kind::culled) << id;
    EXPECT_EQ(s->after_cull(id).reason, "only 'glass' and 'ibl' use it, and those nodes are bypassed") << id;
  }
  EXPECT_EQ(s->after_cull("gtao").kind, Kind::culled);
  EXPECT_EQ(s->after_cull("gtao").reason, "only 'ibl' uses it, and that node is bypassed");
  // sky feeds sh and specular, which are culled themselves: nothing needs it, no bypass to name.
  EXPECT_EQ(s->after_cull("sky").kind, Kind::culled);
  EXPECT_EQ(s->after_cull("sky").reason, "no output depends on it");
  // What the forwarded input needs stays.
  for (const char* id : {"gbuf", "light", "tonemap", "out"}) EXPECT_EQ(s->after_cull(id).kind, Kind::active) << id;
}

TEST(CompilerCull, ABypassedNodeKeepsWhatItForwardsAlive) {
  // A second G-buffer read only by dof's gbuffer input (not forwarded) goes with a pinhole
  // camera; the image dof forwards keeps its producer.
  Graph g = test::load_example("examples/post.json");
  test::add_node(g, "gbuf2", "scene.gbuffer");
  test::remove_link_to(g, "dof.gbuffer");
  test::add_link(g, "gbuf2.gbuffer", "dof.gbuffer");
  auto pinhole = run(g, default_scene_summary());
  EXPECT_EQ(pinhole->after_cull("gbuf2").kind, Kind::culled);
  EXPECT_EQ(pinhole->after_cull("gbuf2").reason, "only 'dof' uses it, and that node is bypassed");
  EXPECT_EQ(pinhole->after_cull("ibl").kind, Kind::active);
  auto lens = run(g, test::load_scene("examples/scenes/thin-lens.json"));
  EXPECT_EQ(lens->after_cull("gbuf2").kind, Kind::active);
}

TEST(CompilerCull, ForwardedInputMapsOutputsToInputs) {
  Graph g = test::load_example("examples/post.json");
  test::node_named(g, "bloom").params.set("intensity", 0);
  auto s = run(std::move(g), default_scene_summary());
  int dof = s->index("dof"), bloom = s->index("bloom");
  EXPECT_EQ(forwarded_input(s->resolved, s->culled, dof, 0), s->resolved.nodes[dof].schema->find_input("color"));
  EXPECT_EQ(forwarded_input(s->resolved, s->culled, bloom, 0), s->resolved.nodes[bloom].schema->find_input("color"));
}

}  // namespace
}  // namespace lg
