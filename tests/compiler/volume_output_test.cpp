// 3D textures in the plan and optional outputs: gi.lpv's and gi.voxel's volume outputs get the
// depth and mips their schemas state (grid^3; resolution^3 with the full chain), and, being
// optional debug views, are written (bound to the pass, placed in memory) only while a link or
// the file's outputs read them or the compile keeps them (`render --dump`): unread, the frame
// does not pay for them.
#include <gtest/gtest.h>

#include "tests/compiler/compiler_fixtures.h"

namespace lg {
namespace {

const PlanResource& plan_resource(const Plan& plan, std::string_view name) {
  const int r = test::resource_at(plan, name);
  if (r < 0) throw std::runtime_error("no resource " + std::string(name));
  return plan.resources[size_t(r)];
}

CompileOptions in_sunlight(bool keep_optional_outputs) {
  CompileOptions options;
  options.scene = test::load_scene("examples/scenes/sun-only.json");  // a directional light
  options.keep_optional_outputs = keep_optional_outputs;
  return options;
}

TEST(VolumeOutputs, GetTheirDepthAndMipsFromTheSchema) {
  Graph lpv = test::load_example("examples/gi-lpv.json");
  test::node_named(lpv, "lpv").params.set("grid", 12.0);
  const Plan lpv_plan = test::compile_ok(lpv, builtin_registry(), in_sunlight(true));
  const LoweredResource& grid = plan_resource(lpv_plan, "lpv.volume").desc;
  EXPECT_EQ(grid.kind, ResourceKind::texture3d);
  EXPECT_EQ(grid.format, "rgba16f");
  EXPECT_EQ(grid.width, 12u);
  EXPECT_EQ(grid.height, 12u);
  EXPECT_EQ(grid.layers, 12u);  // the depth (runtime/gpu/plan_resources.cpp)
  EXPECT_EQ(grid.mips, 1u);
  EXPECT_EQ(grid.bytes, 12u * 12u * 12u * 8u);

  Graph voxel = test::load_example("examples/gi-voxel.json");
  test::node_named(voxel, "voxel").params.set("resolution", 16.0);
  const Plan voxel_plan = test::compile_ok(voxel, builtin_registry(), in_sunlight(true));
  const LoweredResource& voxels = plan_resource(voxel_plan, "voxel.volume").desc;
  EXPECT_EQ(voxels.width, 16u);
  EXPECT_EQ(voxels.layers, 16u);
  EXPECT_EQ(voxels.mips, 5u);  // 16, 8, 4, 2, 1
  // Each mip halves all three sides: 16^3 + 8^3 + 4^3 + 2^3 + 1 texels of 8 bytes.
  EXPECT_EQ(voxels.bytes, (4096u + 512u + 64u + 8u + 1u) * 8u);
}

TEST(VolumeOutputs, AreWrittenOnlyWhenReadOrKept) {
  const Graph graph = test::load_example("examples/gi-lpv.json");
  const Plan unread = test::compile_ok(graph, builtin_registry(), in_sunlight(false));
  EXPECT_EQ(test::resource_in_slot(unread, "lpv/volume", "out.volume"), -1);
  EXPECT_LT(plan_resource(unread, "lpv.volume").placement.block, 0) << "no memory for an output nothing writes";
  EXPECT_GE(test::resource_in_slot(unread, "lpv/volume", "out.irradiance"), 0);

  const Plan kept = test::compile_ok(graph, builtin_registry(), in_sunlight(true));
  EXPECT_EQ(test::resource_in_slot(kept, "lpv/volume", "out.volume"), test::resource_at(kept, "lpv.volume"));
  EXPECT_GE(plan_resource(kept, "lpv.volume").placement.block, 0);

  Graph listed = graph;
  listed.outputs.push_back({test::port_ref("lpv.volume"), {}});
  const Plan read = test::compile_ok(listed, builtin_registry(), in_sunlight(false));
  EXPECT_EQ(test::resource_in_slot(read, "lpv/volume", "out.volume"), test::resource_at(read, "lpv.volume"));
  EXPECT_GE(plan_resource(read, "lpv.volume").placement.block, 0);
}

}  // namespace
}  // namespace lg
