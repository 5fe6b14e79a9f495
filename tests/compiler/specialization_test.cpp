// Specialization seen in the Plan: a scene without what a node or pass needs gets a smaller
// plan, the plan says why, and what is left still reads only what it wrote.
#include <gtest/gtest.h>

#include <algorithm>

#include "graph/plan_format.h"
#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

using test::pass_at;
using test::resource_at;

// Every resource a pass reads was written earlier in the frame, except previous-frame copies
// (and cached results, which are written by the static prefix of the same plan).
void expect_nothing_read_before_written(const Plan& plan) {
  std::vector<char> written(plan.resources.size(), 0);
  for (const auto& p : plan.passes) {
    for (const auto& a : plan.accesses_of(p)) {
      const LoweredResource& r = plan.resources[a.resource].desc;
      if (usage_reads(a.usage) && r.history_of < 0) {
        EXPECT_TRUE(written[a.resource]) << p.name << " reads " << r.name << " before anything writes it";
      }
    }
    for (const auto& a : plan.accesses_of(p))
      if (usage_writes(a.usage)) written[a.resource] = 1;
  }
}

std::vector<std::pair<std::string, std::string>> dropped(const Plan& plan, std::string_view id) {
  const PlanNode* n = test::plan_node(plan, id);
  return n ? n->dropped : std::vector<std::pair<std::string, std::string>>{};
}

TEST(CompilerSpecialization, SunOnlySceneDropsTheAreaLightPass) {
  Plan plan = test::compile_example("examples/default.json", "examples/scenes/sun-only.json");
  const PlanNode* light = test::plan_node(plan, "light");
  ASSERT_NE(light, nullptr);
  EXPECT_EQ(light->state, NodeState::Kind::active);
  const std::pair<std::string, std::string> no_local_shadows{"local_shadows",
                                                             "no point, spot or area light in the scene casts shadows"};
  const std::pair<std::string, std::string> no_emission{"emission",
                                                        "nothing in the scene is drawn with an emissive material"};
  EXPECT_EQ(dropped(plan, "light"), (std::vector<std::pair<std::string, std::string>>{
                                        no_local_shadows, {"area", "the scene has no area lights"}, no_emission}));
  EXPECT_EQ(pass_at(plan, "light/area"), -1);
  EXPECT_GE(pass_at(plan, "light/direct"), 0);
  // light.color is now written once, by direct, and read by ibl.
  int color = resource_at(plan, "light.color");
  ASSERT_GE(color, 0);
  int writers = 0;
  for (const auto& p : plan.passes)
    for (const auto& a : plan.accesses_of(p)) writers += a.resource == color && usage_writes(a.usage);
  EXPECT_EQ(writers, 1);
  EXPECT_NE(plan_to_text(plan).find(
                "passes dropped:\n  light/local_shadows (lighting.deferred): no point, spot or area light in "
                "the scene casts shadows\n  light/area (lighting.deferred): the scene has no area "
                "lights\n"),
            std::string::npos)
      << plan_to_text(plan);
  expect_nothing_read_before_written(plan);

  // The default room has a sphere and a tube light: the pass stays.
  Plan room = test::compile_example("examples/default.json");
  EXPECT_GE(pass_at(room, "light/area"), 0);
  EXPECT_EQ(dropped(room, "light"), (std::vector<std::pair<std::string, std::string>>{no_local_shadows, no_emission}));
}

TEST(CompilerSpecialization, PinholeCameraBypassesDepthOfField) {
  Plan plan = test::compile_example("examples/post.json");  // default scene: aperture 0
  const PlanNode* dof = test::plan_node(plan, "dof");
  ASSERT_NE(dof, nullptr);
  EXPECT_EQ(dof->state, NodeState::Kind::bypassed);
  EXPECT_EQ(dof->reason, "the camera is a pinhole (aperture 0): nothing is out of focus");
  for (const auto& p : plan.passes) EXPECT_NE(p.node, dof - plan.nodes.data()) << p.name;
  // bloom, which consumed dof.color, reads dof's input (ibl.color) directly.
  int ibl = resource_at(plan, "ibl.color");
  ASSERT_GE(ibl, 0);
  EXPECT_EQ(test::resource_in_slot(plan, "bloom/downsample", "in.color"), ibl);
  EXPECT_EQ(test::resource_in_slot(plan, "bloom/composite", "in.color"), ibl);
  EXPECT_EQ(resource_at(plan, "dof.color"), -1);
  EXPECT_NE(plan_to_text(plan).find(
                "bypassed:\n  dof (post.dof): the camera is a pinhole (aperture 0): nothing is out of focus\n"),
            std::string::npos);
  expect_nothing_read_before_written(plan);
}

TEST(CompilerSpecialization, ThinLensCameraKeepsDepthOfField) {
  Plan plan = test::compile_example("examples/post.json", "examples/scenes/thin-lens.json");
  const PlanNode* dof = test::plan_node(plan, "dof");
  ASSERT_NE(dof, nullptr);
  EXPECT_EQ(dof->state, NodeState::Kind::active);
  EXPECT_EQ(dof->reason, "");
  for (const char* pass : {"dof/coc", "dof/gather", "dof/composite"}) EXPECT_GE(pass_at(plan, pass), 0) << pass;
  int color = resource_at(plan, "dof.color");
  ASSERT_GE(color, 0);
  EXPECT_EQ(test::resource_in_slot(plan, "bloom/downsample", "in.color"), color);
  EXPECT_EQ(test::resource_in_slot(plan, "dof/gather", "in.color"), resource_at(plan, "ibl.color"));
  EXPECT_EQ(test::resource_in_slot(plan, "dof/coc", "in.gbuffer"), resource_at(plan, "gbuf.gbuffer.depth"));
  expect_nothing_read_before_written(plan);
}

TEST(CompilerSpecialization, BloomAtIntensityZeroIsBypassed) {
  for (const char* scene : {"", "examples/scenes/thin-lens.json"}) {
    SCOPED_TRACE(scene);
    Graph g = test::load_example("examples/post.json");
    test::node_named(g, "bloom").params.set("intensity", 0);
    CompileOptions o;
    o.scene = test::load_scene(scene);
    Plan plan = test::compile_ok(g, builtin_registry(), o);
    const PlanNode* bloom = test::plan_node(plan, "bloom");
    ASSERT_NE(bloom, nullptr);
    EXPECT_EQ(bloom->state, NodeState::Kind::bypassed);
    EXPECT_TRUE(bloom->reason.starts_with("intensity is 0")) << bloom->reason;
    EXPECT_EQ(bloom->reason, "intensity is 0: bloom would add nothing");
    EXPECT_EQ(pass_at(plan, "bloom/downsample"), -1);
    EXPECT_EQ(resource_at(plan, "bloom/chain"), -1);
    // flare reads what bloom would have read: dof's output, or ibl's when dof is bypassed too.
    const char* upstream = *scene ? "dof.color" : "ibl.color";
    EXPECT_EQ(test::resource_name(plan, test::resource_in_slot(plan, "flare/bright", "in.color")), upstream);
    EXPECT_EQ(test::resource_name(plan, test::resource_in_slot(plan, "flare/composite", "in.color")), upstream);
    expect_nothing_read_before_written(plan);
  }
}

TEST(CompilerSpecialization, FlareAtIntensityZeroIsBypassed) {
  Graph g = test::load_example("examples/post.json");
  test::node_named(g, "flare").params.set("intensity", 0);
  Plan plan = test::compile_ok(g, builtin_registry());
  const PlanNode* flare = test::plan_node(plan, "flare");
  ASSERT_NE(flare, nullptr);
  EXPECT_EQ(flare->state, NodeState::Kind::bypassed);
  EXPECT_EQ(flare->reason, "intensity is 0: the flare would add nothing");
  for (const char* pass : {"flare/bright", "flare/features", "flare/normalise", "flare/composite"})
    EXPECT_EQ(pass_at(plan, pass), -1) << pass;
  EXPECT_EQ(test::resource_name(plan, test::resource_in_slot(plan, "tonemap/map", "in.color")), "bloom.color");
  expect_nothing_read_before_written(plan);
}

TEST(CompilerSpecialization, NoShadowCastersDropsTheShadowPass) {
  SceneSummary no_shadows = default_scene_summary();
  no_shadows.shadows = false;
  SceneSummary area_only = default_scene_summary();
  area_only.directional_lights = 0;  // sphere and tube lights cast no shadow map here
  for (const SceneSummary& scene : {no_shadows, area_only})
    for (const auto& path : test::example_paths()) {
      SCOPED_TRACE(path);
      CompileOptions o;
      o.scene = scene;
      Plan plan = test::compile_ok(test::load_example(path), builtin_registry(), o);
      EXPECT_EQ(dropped(plan, "light"),
                (std::vector<std::pair<std::string, std::string>>{
                    {"shadows", "no light in the scene casts shadows"},
                    {"local_shadows", "no point, spot or area light in the scene casts shadows"},
                    {"emission", "nothing in the scene is drawn with an emissive material"}}));
      EXPECT_EQ(pass_at(plan, "light/shadows"), -1);
      // The shadow map is neither drawn nor sampled, so it takes no memory.
      int map = resource_at(plan, "light/shadow_map");
      if (map >= 0) {
        EXPECT_EQ(plan.resources[map].first, -1);
        EXPECT_EQ(plan.resources[map].placement.block, -1);
      }
      for (const auto& b : plan.barriers) EXPECT_NE(b.resource, map) << "a barrier for a resource nobody uses";
      expect_nothing_read_before_written(plan);
    }
}

// The default scene has no point or spot light, so the default graph neither draws nor keeps
// the local shadow atlas; a spot light with shadows brings both back.
TEST(CompilerSpecialization, LocalShadowsCostNothingWithoutPointOrSpotShadows) {
  SceneSummary spot = default_scene_summary();
  spot.spot_lights = 1;
  spot.local_shadows = true;
  for (const auto& path : test::example_paths()) {
    SCOPED_TRACE(path);
    CompileOptions o;
    Plan plain = test::compile_ok(test::load_example(path), builtin_registry(), o);
    EXPECT_EQ(pass_at(plain, "light/local_shadows"), -1);
    const int atlas = resource_at(plain, "light/local_shadow_atlas");
    if (atlas >= 0) {
      EXPECT_EQ(plain.resources[atlas].placement.block, -1);
    }
    o.scene = spot;
    Plan lit = test::compile_ok(test::load_example(path), builtin_registry(), o);
    if (pass_at(lit, "light/direct") < 0) continue;  // a graph without deferred lighting
    EXPECT_GE(pass_at(lit, "light/local_shadows"), 0);
    EXPECT_LT(pass_at(lit, "light/local_shadows"), pass_at(lit, "light/direct"));
    EXPECT_GE(lit.resources[resource_at(lit, "light/local_shadow_atlas")].placement.block, 0);
    expect_nothing_read_before_written(lit);
  }
}

// The emission pass adds the G-buffer's emissive target onto the lit image only for scenes that
// draw an emissive material; otherwise the plan drops it with the reason.
TEST(CompilerSpecialization, EmissionPassRunsOnlyForEmissiveMaterials) {
  Plan plain = test::compile_example("examples/default.json");
  EXPECT_EQ(pass_at(plain, "light/emission"), -1);
  const auto drops = dropped(plain, "light");
  EXPECT_NE(std::find(drops.begin(), drops.end(),
                      std::pair<std::string, std::string>{"emission",
                                                          "nothing in the scene is drawn with an emissive material"}),
            drops.end());

  CompileOptions emissive;
  emissive.scene.emissive_materials = true;
  Plan lit = test::compile_ok(test::load_example("examples/default.json"), builtin_registry(), emissive);
  const int emission = pass_at(lit, "light/emission");
  ASSERT_GE(emission, 0);
  EXPECT_LT(pass_at(lit, "light/direct"), emission);
  EXPECT_LT(emission, pass_at(lit, "ibl/shade"));
  expect_nothing_read_before_written(lit);
}

TEST(CompilerSpecialization, NoEnvironmentBypassesImageBasedLighting) {
  SceneSummary dark = default_scene_summary();
  dark.environment = false;
  CompileOptions o;
  o.scene = dark;
  Plan plan = test::compile_ok(test::load_example("examples/default.json"), builtin_registry(), o);
  EXPECT_EQ(test::plan_node(plan, "ibl")->state, NodeState::Kind::bypassed);
  EXPECT_EQ(test::plan_node(plan, "ibl")->reason, "the scene has no environment light");
  EXPECT_EQ(test::resource_name(plan, test::resource_in_slot(plan, "tonemap/map", "in.color")), "light.color");
  // Nothing static is left to compute, and gtao only fed ibl.
  for (const auto& p : plan.passes) EXPECT_FALSE(p.is_static) << p.name;
  EXPECT_EQ(test::plan_node(plan, "gtao")->state, NodeState::Kind::culled);
  expect_nothing_read_before_written(plan);
}

// examples/gi-volume.json feeds gi.irradiance_volume into lighting.ibl's optional input. A scene
// without volumes bypasses the volume node forwarding null: ibl then runs with the input unlinked
// (its shade pass reads no volume image). lighting.ibl's own bypass (no environment light) holds
// "unless_linked" irradiance_volume: a sealed room lit by lamps and a volume keeps its bounce
// light, a scene with neither environment nor volumes bypasses ibl. Fails if a null forward still
// counts as a link, or if unless_linked is ignored.
TEST(CompilerSpecialization, VolumeBypassForwardsNullAndKeepsIblOnlyWhileLinked) {
  const auto compile = [](bool environment, int volumes) {
    CompileOptions o;
    o.scene = default_scene_summary();
    o.scene.environment = environment;
    o.scene.irradiance_volumes = volumes;
    return test::compile_ok(test::load_example("examples/gi-volume.json"), builtin_registry(), o);
  };
  const Plan lit = compile(true, 0);
  EXPECT_EQ(test::plan_node(lit, "volume")->state, NodeState::Kind::bypassed);
  EXPECT_EQ(test::plan_node(lit, "volume")->reason, "the scene has no irradiance volumes");
  EXPECT_EQ(test::plan_node(lit, "ibl")->state, NodeState::Kind::active);
  EXPECT_EQ(test::resource_in_slot(lit, "ibl/shade", "in.irradiance_volume"), -1);
  EXPECT_EQ(test::resource_at(lit, "volume.irradiance"), -1);
  expect_nothing_read_before_written(lit);

  const Plan lamps = compile(false, 1);
  EXPECT_EQ(test::plan_node(lamps, "volume")->state, NodeState::Kind::active);
  EXPECT_EQ(test::plan_node(lamps, "ibl")->state, NodeState::Kind::active);
  EXPECT_EQ(test::resource_name(lamps, test::resource_in_slot(lamps, "ibl/shade", "in.irradiance_volume")),
            "volume.irradiance");
  expect_nothing_read_before_written(lamps);

  const Plan dark = compile(false, 0);
  EXPECT_EQ(test::plan_node(dark, "ibl")->state, NodeState::Kind::bypassed);
  EXPECT_EQ(test::plan_node(dark, "ibl")->reason, "the scene has no environment light");
  EXPECT_EQ(test::resource_name(dark, test::resource_in_slot(dark, "tonemap/map", "in.color")), "light.color");
  expect_nothing_read_before_written(dark);
}

// A scene without reflection probes bypasses gi.reflection_capture with the reason in the plan,
// and lighting.ibl then runs with its reflection_probes input unlinked; with a probe the capture
// runs and feeds it, with or without an environment light (a room lit by lamps keeps its
// reflections: lighting.ibl's bypass holds unless the volume or the probes are linked). Fails
// without the node's bypass (it would run, and fail, with no probes).
TEST(CompilerSpecialization, ReflectionCaptureBypassForwardsNullWithoutProbes) {
  const auto compile = [](int probes, bool environment = true) {
    CompileOptions o;
    o.scene = default_scene_summary();
    o.scene.environment = environment;
    o.scene.reflection_probes = probes;
    return test::compile_ok(test::load_example("examples/reflection-probes.json"), builtin_registry(), o);
  };
  const Plan none = compile(0);
  EXPECT_EQ(test::plan_node(none, "probes")->state, NodeState::Kind::bypassed);
  EXPECT_EQ(test::plan_node(none, "probes")->reason, "the scene has no reflection probes");
  EXPECT_EQ(test::plan_node(none, "ibl")->state, NodeState::Kind::active);
  EXPECT_EQ(test::resource_in_slot(none, "ibl/shade", "in.reflection_probes"), -1);
  EXPECT_EQ(pass_at(none, "probes/lookup"), -1);
  expect_nothing_read_before_written(none);

  const Plan one = compile(1);
  EXPECT_EQ(test::plan_node(one, "probes")->state, NodeState::Kind::active);
  EXPECT_EQ(test::resource_name(one, test::resource_in_slot(one, "ibl/shade", "in.reflection_probes")),
            "probes.reflections");
  EXPECT_LT(pass_at(one, "probes/lookup"), pass_at(one, "ibl/shade"));
  expect_nothing_read_before_written(one);

  const Plan lamps = compile(1, false);
  EXPECT_EQ(test::plan_node(lamps, "ibl")->state, NodeState::Kind::active);
  EXPECT_EQ(test::resource_name(lamps, test::resource_in_slot(lamps, "ibl/shade", "in.reflection_probes")),
            "probes.reflections");
  const Plan dark = compile(0, false);
  EXPECT_EQ(test::plan_node(dark, "ibl")->state, NodeState::Kind::bypassed);
  expect_nothing_read_before_written(dark);
}

// gi.reflection_capture's raster capture draws the environment's light into the probes: under an
// environment it needs 'specular', 'brdf_lut' and 'sh' or 'irradiance' linked. Unlinked, the
// compiler refuses the graph at the node's line and column, naming the inputs (it used to fail
// only when the pass ran); 'path_traced', a scene without an environment, or one without probes
// (the node bypassed) need none. Fails if the rule is not checked, or checked for bypassed nodes.
TEST(CompilerSpecialization, RasterCaptureUnderAnEnvironmentNeedsTheEnvironmentLinked) {
  Graph unlinked = test::load_example("examples/reflection-probes.json");
  std::erase_if(unlinked.links, [](const GraphLink& l) {
    return l.to.node == "probes" && (l.to.port == "specular" || l.to.port == "sh");
  });
  const auto options = [](bool environment, int probes) {
    CompileOptions o;
    o.scene = default_scene_summary();
    o.scene.environment = environment;
    o.scene.reflection_probes = probes;
    return o;
  };
  const std::string errors = test::compile_errors(unlinked, builtin_registry(), options(true, 1));
  const GraphNode& probes =
      *std::find_if(unlinked.nodes.begin(), unlinked.nodes.end(), [](const GraphNode& n) { return n.id == "probes"; });
  const std::string at = "examples/reflection-probes.json:" + std::to_string(probes.pos.line) + ":" +
                         std::to_string(probes.pos.column) + ": error: node 'probes' (gi.reflection_capture) needs ";
  EXPECT_NE(errors.find(at + "its input 'specular' linked to something that runs: capture 'raster' draws the "
                             "environment's light into the probes"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find(at + "one of its inputs 'sh' or 'irradiance' linked"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("'brdf_lut'"), std::string::npos) << errors;  // still linked

  Graph traced = unlinked;
  for (GraphNode& n : traced.nodes)
    if (n.id == "probes") n.params.set("capture", "path_traced");
  EXPECT_EQ(test::plan_node(test::compile_ok(traced, builtin_registry(), options(true, 1)), "probes")->state,
            NodeState::Kind::active);
  EXPECT_EQ(test::plan_node(test::compile_ok(unlinked, builtin_registry(), options(false, 1)), "probes")->state,
            NodeState::Kind::active);
  EXPECT_EQ(test::plan_node(test::compile_ok(unlinked, builtin_registry(), options(true, 0)), "probes")->state,
            NodeState::Kind::bypassed);
}

// The default graph composites transparent surfaces after the image-based light; a scene with no
// BLEND material bypasses that node (it forwards ibl's colour, and the plan says why), leaving
// the passes, resources and barriers the graph had before the node was wired in. Fails without
// the blend_materials scene feature (the node runs for every scene, or the graph does not load).
TEST(CompilerSpecialization, ForwardTransparentRunsOnlyForBlendMaterials) {
  Plan plan = test::compile_example("examples/default.json");
  const PlanNode* glass = test::plan_node(plan, "glass");
  ASSERT_NE(glass, nullptr);
  EXPECT_EQ(glass->state, NodeState::Kind::bypassed);
  EXPECT_EQ(glass->reason, "nothing in the scene is drawn with a BLEND (transparent) material");
  EXPECT_EQ(pass_at(plan, "glass/composite"), -1);

  Graph before = test::load_example("examples/default.json");  // tone mapping ibl's colour directly
  ASSERT_TRUE(test::remove_link_to(before, "tonemap.color"));
  test::add_link(before, "ibl.color", "tonemap.color");
  Plan base = test::compile_ok(before, builtin_registry());
  ASSERT_EQ(plan.passes.size(), base.passes.size());
  for (size_t p = 0; p < plan.passes.size(); ++p) EXPECT_EQ(plan.passes[p].name, base.passes[p].name);
  ASSERT_EQ(plan.resources.size(), base.resources.size());
  for (size_t r = 0; r < plan.resources.size(); ++r)
    EXPECT_EQ(plan.resources[r].desc.name, base.resources[r].desc.name);
  EXPECT_EQ(plan.barriers.size(), base.barriers.size());

  CompileOptions blend;
  blend.scene.blend_materials = true;
  Plan with_glass = test::compile_ok(test::load_example("examples/default.json"), builtin_registry(), blend);
  EXPECT_EQ(test::plan_node(with_glass, "glass")->state, NodeState::Kind::active);
  const int composite = pass_at(with_glass, "glass/composite");
  ASSERT_GE(composite, 0);
  EXPECT_LT(pass_at(with_glass, "ibl/shade"), composite);
  EXPECT_LT(composite, pass_at(with_glass, "tonemap/map"));
  expect_nothing_read_before_written(with_glass);
}

}  // namespace
}  // namespace lg
