// The example graphs a user runs first: each compiles with every example scene, the passes come
// in the order a renderer must run them, and nothing is culled unless the graph asks for it.
#include <gtest/gtest.h>

#include <algorithm>

#include "graph/plan_format.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

using test::pass_at;

// `a` runs before `b` when both are in the plan; fails when either is missing.
void expect_before(const Plan& plan, std::string_view a, std::string_view b) {
  int pa = pass_at(plan, a), pb = pass_at(plan, b);
  ASSERT_GE(pa, 0) << "missing " << a;
  ASSERT_GE(pb, 0) << "missing " << b;
  EXPECT_LT(pa, pb) << a << " must run before " << b;
}

// The order a deferred renderer must keep, for whichever of these passes a plan has: the
// examples name their nodes alike, so one list serves them all (and new ones).
const std::pair<const char*, const char*> must_precede[] = {
    {"gbuf/raster", "light/shadows"},
    {"light/shadows", "light/direct"},
    {"gbuf/raster", "light/direct"},
    {"light/direct", "light/area"},  // area lights add onto direct light
    {"light/direct", "ibl/shade"},
    {"light/area", "ibl/shade"},
    {"sky/render", "sh/project"},
    {"sky/render", "specular/prefilter"},
    {"sh/project", "ibl/shade"},
    {"specular/prefilter", "ibl/shade"},
    {"dfg/integrate", "ibl/shade"},
    {"gbuf/raster", "gtao/prefilter"},
    {"gtao/prefilter", "gtao/horizons"},
    {"gtao/horizons", "gtao/denoise"},
    {"gtao/denoise", "ibl/shade"},
    {"gbuf/raster", "volume/lookup"},
    {"volume/lookup", "ibl/shade"},  // the probe volume's irradiance feeds image-based light
    {"gbuf/raster", "ssr/hiz"},
    {"ssr/hiz", "ssr/trace"},
    {"light/direct", "ssr/trace"},  // the reflections reflect this frame's direct light
    {"ssr/trace", "ibl/shade"},
    {"probes/lookup", "planar/reflect"},  // the planes pass the probes' reflections through
    {"planar/reflect", "ibl/shade"},
    {"ibl/shade", "dof/coc"},
    {"dof/coc", "dof/gather"},
    {"dof/gather", "dof/composite"},
    {"ibl/shade", "bloom/downsample"},
    {"dof/composite", "bloom/downsample"},
    {"bloom/downsample", "bloom/upsample"},
    {"bloom/upsample", "bloom/composite"},
    {"bloom/composite", "tonemap/map"},
    {"ibl/shade", "tonemap/map"},
    {"light/area", "tonemap/map"},
    {"light/direct", "tonemap/map"},
};

TEST(CompilerExamples, TheKnownExamplesAreAllFound) {
  for (const char* known : {"examples/default.json", "examples/minimal.json", "examples/post.json"})
    EXPECT_NE(std::find(test::example_paths().begin(), test::example_paths().end(), known), test::example_paths().end())
        << known;
  for (const char* known :
       {"examples/scenes/default.json", "examples/scenes/sun-only.json", "examples/scenes/thin-lens.json"})
    EXPECT_NE(std::find(test::scene_paths().begin(), test::scene_paths().end(), known), test::scene_paths().end())
        << known;
}

TEST(CompilerExamples, EveryExampleCompilesWithEveryScene) {
  int relations = 0;
  for (const auto& path : test::example_paths())
    for (const auto& scene : test::scene_paths()) {
      SCOPED_TRACE(path + " with scene '" + scene + "'");
      CompileOptions options;
      options.scene = test::load_scene(scene);
      Graph g = test::load_example(path);
      Diagnostics d(path);
      CompileResult result = compile(g, builtin_registry(), options, d);
      ASSERT_TRUE(result.plan) << d.to_string();
      EXPECT_TRUE(d.items().empty()) << "no warnings either:\n" << d.to_string();
      const Plan& plan = *result.plan;
      EXPECT_EQ(plan.scene, options.scene.name);
      ASSERT_FALSE(plan.passes.empty());
      EXPECT_FALSE(plan.barriers.empty());

      // Nothing is culled in the examples; only depth of field may be bypassed, without a lens,
      // the irradiance volume without volumes, the transparent surfaces' pass without BLEND
      // materials, screen-space reflections without glossy materials, the reflection probes'
      // capture without probes and the planar reflections without reflectors.
      for (const auto& n : plan.nodes) {
        EXPECT_NE(n.state, NodeState::Kind::culled) << n.id << ": " << n.reason;
        bool lens = options.scene.aperture > 0, volumes = options.scene.irradiance_volumes > 0;
        bool bypassed = (n.type == "post.dof" && !lens) || (n.type == "gi.irradiance_volume" && !volumes) ||
                        (n.type == "scene.forward_transparent" && !options.scene.blend_materials) ||
                        (n.type == "lighting.ssr" && !options.scene.glossy_materials) ||
                        (n.type == "gi.reflection_capture" && options.scene.reflection_probes == 0) ||
                        (n.type == "gi.planar_reflection" && options.scene.planar_reflectors == 0);
        auto expected = bypassed ? NodeState::Kind::bypassed : NodeState::Kind::active;
        EXPECT_EQ(n.state, expected) << n.id << ": " << n.reason;
      }
      for (auto [a, b] : must_precede)
        if (pass_at(plan, a) >= 0 && pass_at(plan, b) >= 0) {
          expect_before(plan, a, b);
          ++relations;
        }
      // The static passes (environment maps, the BRDF table) come first, as one block.
      bool dynamic = false;
      for (const auto& p : plan.passes) {
        if (!p.is_static)
          dynamic = true;
        else
          EXPECT_FALSE(dynamic) << p.name << " is static but runs after a per-frame pass";
      }
      // Every example ends by tone mapping what the display shows, a result of the frame.
      EXPECT_EQ(plan.passes.back().name, "tonemap/map");
      int shown = test::resource_at(plan, "tonemap.color");
      ASSERT_GE(shown, 0);
      EXPECT_EQ(plan.resources[shown].desc.lifetime, ResourceLifetime::exported);
    }
  EXPECT_GT(relations, 100);  // the list above matched the examples, it did not skip them all
}

TEST(CompilerExamples, TheKnownExamplesHaveTheirCorePasses) {
  for (const char* path : {"examples/default.json", "examples/minimal.json", "examples/post.json"}) {
    Plan plan = test::compile_example(path);
    for (const char* pass : {"gbuf/raster", "light/shadows", "light/direct", "light/area", "tonemap/map"})
      EXPECT_GE(pass_at(plan, pass), 0) << path << ": " << pass;
  }
  Plan d = test::compile_example("examples/default.json");
  for (const char* pass : {"sky/render", "sh/project", "specular/prefilter", "dfg/integrate"}) {
    int p = pass_at(d, pass);
    ASSERT_GE(p, 0) << pass;
    EXPECT_LT(p, 4) << pass << ": the four static environment passes run first";
  }
  for (const char* pass : {"gtao/prefilter", "gtao/horizons", "gtao/denoise", "ibl/shade"})
    EXPECT_GE(pass_at(d, pass), 0);
  Plan post = test::compile_example("examples/post.json", "examples/scenes/thin-lens.json");
  for (const char* pass : {"dof/coc", "dof/gather", "dof/composite", "bloom/downsample", "bloom/composite"})
    EXPECT_GE(pass_at(post, pass), 0) << pass;
}

TEST(CompilerExamples, AFileOutputIsExported) {
  Plan plan = test::compile_example("examples/post.json");
  int ibl = test::resource_at(plan, "ibl.color");
  ASSERT_GE(ibl, 0);
  EXPECT_EQ(plan.resources[ibl].desc.lifetime, ResourceLifetime::exported);
  EXPECT_EQ(plan.resources[ibl].last, static_cast<int>(plan.passes.size()) - 1);
}

TEST(CompilerExamples, AnUnusedNodeIsCulledWithItsReason) {
  Graph g = test::load_example("examples/default.json");
  test::add_node(g, "ssao", "occlusion.ssao");
  test::add_link(g, "gbuf.gbuffer", "ssao.gbuffer");
  Plan plan = test::compile_ok(g, builtin_registry());
  const PlanNode* ssao = test::plan_node(plan, "ssao");
  ASSERT_NE(ssao, nullptr);
  EXPECT_EQ(ssao->state, NodeState::Kind::culled);
  EXPECT_EQ(ssao->reason, "no output depends on it");
  for (const auto& p : plan.passes) EXPECT_FALSE(p.name.starts_with("ssao")) << p.name;
  for (const auto& r : plan.resources) EXPECT_FALSE(r.desc.name.starts_with("ssao")) << r.desc.name;
  // The reader sees it too.
  EXPECT_NE(plan_to_text(plan).find("culled:\n  ssao (occlusion.ssao): no output depends on it\n"), std::string::npos)
      << plan_to_text(plan);
  // And the rest of the plan is unchanged.
  Plan base = test::compile_example("examples/default.json");
  ASSERT_EQ(plan.passes.size(), base.passes.size());
  for (size_t p = 0; p < plan.passes.size(); ++p) EXPECT_EQ(plan.passes[p].name, base.passes[p].name);
}

TEST(CompilerExamples, ANodeOnlyABypassedNodeUsesIsCulledNamingIt) {
  // dof reads depth from its own G-buffer; with a pinhole camera dof is bypassed and forwards
  // only its colour, so that G-buffer is not needed.
  Graph g = test::load_example("examples/post.json");
  test::add_node(g, "dof_depth", "scene.gbuffer", [] {
    JsonValue p = JsonValue::object();
    p.set("resolution_scale", 0.5);
    return p;
  }());
  test::remove_link_to(g, "dof.gbuffer");
  test::add_link(g, "dof_depth.gbuffer", "dof.gbuffer");
  Plan plan = test::compile_ok(g, builtin_registry());
  const PlanNode* node = test::plan_node(plan, "dof_depth");
  ASSERT_NE(node, nullptr);
  EXPECT_EQ(node->state, NodeState::Kind::culled);
  EXPECT_EQ(node->reason, "only 'dof' uses it, and that node is bypassed");
  EXPECT_EQ(pass_at(plan, "dof_depth/raster"), -1);

  CompileOptions lens;
  lens.scene = test::load_scene("examples/scenes/thin-lens.json");
  Plan with_lens = test::compile_ok(g, builtin_registry(), lens);
  EXPECT_EQ(test::plan_node(with_lens, "dof_depth")->state, NodeState::Kind::active);
  expect_before(with_lens, "dof_depth/raster", "dof/coc");
}

TEST(CompilerExamples, ScreenSpaceReflectionsAreBypassedWithoutGlossyMaterials) {
  Plan glossy = test::compile_example("examples/ssr.json");
  EXPECT_EQ(test::plan_node(glossy, "ssr")->state, NodeState::Kind::active);
  expect_before(glossy, "ssr/trace", "ibl/shade");
  CompileOptions matte;
  matte.scene = test::load_scene("examples/scenes/probe-room.json");
  ASSERT_FALSE(matte.scene.glossy_materials);
  Plan plan = test::compile_ok(test::load_example("examples/ssr.json"), builtin_registry(), matte);
  const PlanNode* ssr = test::plan_node(plan, "ssr");
  ASSERT_NE(ssr, nullptr);
  EXPECT_EQ(ssr->state, NodeState::Kind::bypassed);
  EXPECT_EQ(ssr->reason, "the scene has no glossy materials");
  for (const auto& p : plan.passes) EXPECT_FALSE(p.name.starts_with("ssr/")) << p.name;
}

TEST(CompilerExamples, PlanarReflectionIsBypassedWithoutReflectors) {
  CompileOptions mirror;
  mirror.scene.planar_reflectors = 1;
  Plan with = test::compile_ok(test::load_example("examples/planar-reflections.json"), builtin_registry(), mirror);
  EXPECT_EQ(test::plan_node(with, "planar")->state, NodeState::Kind::active);
  expect_before(with, "planar/reflect", "ibl/shade");
  Plan without = test::compile_example("examples/planar-reflections.json");  // the default scene has none
  const PlanNode* planar = test::plan_node(without, "planar");
  ASSERT_NE(planar, nullptr);
  EXPECT_EQ(planar->state, NodeState::Kind::bypassed);
  EXPECT_EQ(planar->reason, "the scene has no planar reflectors");
}

TEST(CompilerExamples, TheTextPlanNamesEveryPassInOrder) {
  // What `lumagraph compile` prints: one row per pass, in plan order, and the memory summary.
  Plan plan = test::compile_example("examples/default.json");
  std::string text = plan_to_text(plan);
  size_t at = 0;
  for (const auto& p : plan.passes) {
    size_t found = text.find(" " + p.name + " ", at);
    ASSERT_NE(found, std::string::npos) << p.name << " missing or out of order in:\n" << text;
    at = found;
  }
  EXPECT_NE(text.find("memory: transient "), std::string::npos);
  EXPECT_NE(text.find(std::to_string(plan.barriers.size()) + " barriers"), std::string::npos);
}

}  // namespace
}  // namespace lg
