// The executor on lavapipe with validation and synchronization validation: test graphs run for
// several frames and their results are read back and compared exactly (every value written is
// exact in half precision). Covers chains of passes, a sampled input, an internal resource,
// aliasing, history (frame N sees N), cached static passes, buffers, outputs by name, errors
// that name the node or the pass, memory use against the plan, and an adopted host device.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <functional>

#include "graph/json_writer.h"
#include "runtime/exec/executor.h"
#include "runtime/exec/executor_error.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/context.h"
#include "runtime/scene/scene_view.h"
#include "tests/runtime/exec_fixtures.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr uint32_t width = 40, height = 24;  // not multiples of the 8x8 groups

struct NodeKernelStub final : NodeKernel {
  void record(PassContext&) override {}
};

using Texel = std::array<float, 4>;

// Counts texels that differ from `want(x, y)`, reporting the first few.
int wrong_texels(const std::vector<float>& texels, const std::function<Texel(uint32_t, uint32_t)>& want) {
  EXPECT_EQ(texels.size(), size_t{width} * height * 4);
  if (texels.size() != size_t{width} * height * 4) return -1;
  int wrong = 0;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const float* t = &texels[(y * width + x) * 4];
      const Texel w = want(x, y);
      if (std::memcmp(t, w.data(), sizeof w) != 0 && ++wrong <= 3)
        ADD_FAILURE() << "texel " << x << "," << y << ": " << t[0] << " " << t[1] << " " << t[2] << " " << t[3]
                      << ", want " << w[0] << " " << w[1] << " " << w[2] << " " << w[3];
    }
  return wrong;
}

// (red, x, y, 1): a fill plus whatever was added to red on the way.
std::function<Texel(uint32_t, uint32_t)> filled(float red) {
  return [red](uint32_t x, uint32_t y) { return Texel{red, float(x), float(y), 1}; };
}

class ExecTest : public GpuTest {
 protected:
  TestKernels kernels = test_kernels();
  SceneView scene;

  std::unique_ptr<Executor> executor(std::string_view graph, bool alias = true) {
    return std::make_unique<Executor>(context(), kernels.registry, compile_test_graph(context(), graph, alias));
  }
};

constexpr std::string_view chain_graph = R"({ "format": "lumagraph/1", "name": "chain",
  "nodes": [ { "id": "fill", "type": "test.fill", "params": { "value": 0.25 } },
             { "id": "add", "type": "test.add", "params": { "add": 1 } },
             { "id": "two", "type": "test.two_pass" },
             { "id": "out", "type": "test.display" } ],
  "links": [ { "from": "fill.color", "to": "add.src" }, { "from": "add.color", "to": "two.src" },
             { "from": "two.color", "to": "out.color" } ] })";

TEST_F(ExecTest, RunsAChainOfPassesFrameAfterFrame) {
  auto exec = executor(chain_graph);
  GpuScene gpu_scene(context());
  for (uint64_t frame = 0; frame < 3; ++frame) {
    FrameStats stats = exec->run_frame(scene, gpu_scene);
    EXPECT_EQ(stats.frame, frame);
    ASSERT_EQ(stats.passes.size(), 4u);
    EXPECT_EQ(stats.passes[0].name, "fill/fill");
    EXPECT_EQ(stats.passes[3].name, "two/second");
    for (const PassStats& p : stats.passes) EXPECT_FALSE(p.cached) << p.name;
    EXPECT_EQ(wrong_texels(exec->read_image("two.color"), filled(3.25f)), 0) << "frame " << frame;
  }
  EXPECT_EQ(exec->frames_run(), 3u);
  EXPECT_EQ(exec->layout("two.color"), VK_IMAGE_LAYOUT_GENERAL);
}

TEST_F(ExecTest, FindsOutputsByName) {
  auto exec = executor(chain_graph);
  GpuScene gpu_scene(context());
  exec->run_frame(scene, gpu_scene);
  EXPECT_EQ(exec->output_names(), std::vector<std::string>{"main"});
  EXPECT_EQ(exec->output_resource("main"), "two.color");
  EXPECT_EQ(&exec->output_image("main"), &exec->image("two.color"));
  EXPECT_EQ(wrong_texels(exec->read_image(exec->output_resource("main")), filled(3.25f)), 0);
  try {
    exec->output_resource("hud");
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_STREQ(e.what(), "no output node is named 'hud'; the plan has 'main'");
  }
  try {
    exec->read_image("two.colour");
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_NE(std::string(e.what()).find("no resource 'two.colour'; it has fill.color, add.color"), std::string::npos)
        << e.what();
  }
}

TEST_F(ExecTest, ReadingBeforeTheFirstFrameIsAnError) {
  auto exec = executor(chain_graph);
  EXPECT_EQ(exec->layout("two.color"), VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_THROW(exec->read_image("two.color"), ExecutorError);
}

// fill -> a -> b -> c: the internal images and the links between nodes share bytes once
// their lifetimes end, and the results are still exact.
constexpr std::string_view aliased_graph = R"({ "format": "lumagraph/1",
  "nodes": [ { "id": "fill", "type": "test.fill", "params": { "value": 0.5 } },
             { "id": "a", "type": "test.two_pass" }, { "id": "b", "type": "test.two_pass" },
             { "id": "c", "type": "test.two_pass" }, { "id": "out", "type": "test.display" } ],
  "links": [ { "from": "fill.color", "to": "a.src" }, { "from": "a.color", "to": "b.src" },
             { "from": "b.color", "to": "c.src" }, { "from": "c.color", "to": "out.color" } ] })";

TEST_F(ExecTest, AliasedResourcesKeepResultsExact) {
  auto exec = executor(aliased_graph);
  const Plan& plan = exec->plan();
  ASSERT_TRUE(plan.blocks[0].aliased);
  ASSERT_LT(plan.memory.transient, plan.memory.transient_unaliased);
  EXPECT_TRUE(std::any_of(plan.barriers.begin(), plan.barriers.end(),
                          [](const Barrier& b) { return b.reason == BarrierReason::alias; }));
  GpuScene gpu_scene(context());
  for (int frame = 0; frame < 3; ++frame) {
    exec->run_frame(scene, gpu_scene);
    EXPECT_EQ(wrong_texels(exec->read_image("c.color"), filled(6.5f)), 0) << "frame " << frame;
  }
  const std::vector<std::string> readable = exec->readable_resources();
  EXPECT_NE(std::find(readable.begin(), readable.end(), "c.color"), readable.end());
  EXPECT_EQ(std::find(readable.begin(), readable.end(), "fill.color"), readable.end());
  // fill.color's bytes are reused later in the frame: reading it would show another image.
  try {
    exec->read_image("fill.color");
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_STREQ(e.what(),
                 "cannot read 'fill.color': later passes of the frame reuse its memory (compile without "
                 "aliasing to read it)");
  }
}

TEST_F(ExecTest, WithoutAliasingEveryIntermediateReadsBack) {
  auto exec = executor(aliased_graph, false);
  GpuScene gpu_scene(context());
  exec->run_frame(scene, gpu_scene);
  EXPECT_EQ(exec->readable_resources().size(), exec->plan().resources.size());
  EXPECT_EQ(wrong_texels(exec->read_image("fill.color"), filled(0.5f)), 0);
  EXPECT_EQ(wrong_texels(exec->read_image("a/tmp"), filled(1.5f)), 0);
  EXPECT_EQ(wrong_texels(exec->read_image("b.color"), filled(4.5f)), 0);
}

TEST_F(ExecTest, HistoryFrameNSeesWhatFrameNMinusOneWrote) {
  auto exec = executor(R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "acc", "type": "test.accumulate" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "acc.color", "to": "acc.history" }, { "from": "acc.color", "to": "out.color" } ] })");
  GpuScene gpu_scene(context());
  const auto red = [](float r) { return [r](uint32_t, uint32_t) { return Texel{r, 0, 0, 0}; }; };
  for (int frame = 0; frame < 4; ++frame) {
    exec->run_frame(scene, gpu_scene);
    // The first frame reads cleared history; each frame adds one to the one before.
    EXPECT_EQ(wrong_texels(exec->read_image("acc.color@previous"), red(float(frame))), 0) << "frame " << frame;
    EXPECT_EQ(wrong_texels(exec->read_image("acc.color"), red(float(frame + 1))), 0) << "frame " << frame;
    EXPECT_EQ(wrong_texels(exec->read_image(exec->output_resource("main")), red(float(frame + 1))), 0);
  }
  EXPECT_EQ(exec->layout("acc.color@previous"), VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
}

constexpr std::string_view static_graph = R"({ "format": "lumagraph/1",
  "nodes": [ { "id": "bake", "type": "test.bake", "params": { "value": 0.5 } },
             { "id": "add", "type": "test.add", "params": { "add": 2 } },
             { "id": "out", "type": "test.display", "params": { "name": "final" } } ],
  "links": [ { "from": "bake.color", "to": "add.src" }, { "from": "add.color", "to": "out.color" } ] })";

TEST_F(ExecTest, StaticPassesRunOnceThenAreSkippedAsCached) {
  auto exec = executor(static_graph);
  ASSERT_TRUE(exec->plan().passes[0].is_static);
  ASSERT_TRUE(std::any_of(exec->plan().barriers.begin(), exec->plan().barriers.end(),
                          [](const Barrier& b) { return b.skip_when_cached; }));
  GpuScene gpu_scene(context());
  auto& calls = *kernels.calls;
  for (int frame = 0; frame < 3; ++frame) {
    FrameStats stats = exec->run_frame(scene, gpu_scene);
    ASSERT_EQ(stats.passes.size(), 2u);
    EXPECT_EQ(stats.passes[0].name, "bake/fill");
    EXPECT_EQ(stats.passes[0].cached, frame > 0) << "frame " << frame;
    EXPECT_EQ(stats.passes[0].gpu_ms, frame > 0 ? 0.0 : stats.passes[0].gpu_ms);
    EXPECT_FALSE(stats.passes[1].cached);
    EXPECT_EQ(calls["test.bake"], 1) << "frame " << frame;
    EXPECT_EQ(calls["test.add"], frame + 1);
    EXPECT_EQ(wrong_texels(exec->read_image(exec->output_resource("final")), filled(2.5f)), 0) << "frame " << frame;
  }
  EXPECT_EQ(exec->layout("bake.color"), VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  exec->invalidate_cache();
  FrameStats again = exec->run_frame(scene, gpu_scene);
  EXPECT_FALSE(again.passes[0].cached);
  EXPECT_EQ(calls["test.bake"], 2);
  EXPECT_EQ(wrong_texels(exec->read_image("bake.color"), filled(0.5f)), 0);
  EXPECT_TRUE(exec->run_frame(scene, gpu_scene).passes[0].cached);
}

TEST_F(ExecTest, DrawsTheGpuScenesMeshIntoAnAttachment) {
  auto exec = executor(R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "raster", "type": "test.raster" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "raster.color", "to": "out.color" } ] })");
  // One triangle covering the frame, in clip space; no uvs (they read as 0).
  scene.version = 1;
  MeshData mesh;
  mesh.name = "cover";
  mesh.positions = {{-1, -1, 0.5f}, {3, -1, 0.5f}, {-1, 3, 0.5f}};
  mesh.normals.assign(3, {0.25f, 0.5f, 0.75f});
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(std::make_shared<const MeshData>(std::move(mesh)));
  GpuScene gpu_scene(context());
  for (int frame = 0; frame < 2; ++frame) {
    exec->run_frame(scene, gpu_scene);
    EXPECT_EQ(wrong_texels(exec->read_image("raster.color"),
                           [](uint32_t, uint32_t) {
                             return Texel{0.25f, 0.5f, 0.75f, 1};
                           }),
              0);
  }
  EXPECT_EQ(exec->layout("raster.color"), VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL);
}

TEST_F(ExecTest, ReadsBuffersAsBytes) {
  auto exec = executor(R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "sh", "type": "test.sh", "params": { "order": 2, "value": 3 } } ],
    "outputs": [ "sh.sh" ] })");
  GpuScene gpu_scene(context());
  exec->run_frame(scene, gpu_scene);
  std::vector<std::byte> bytes = exec->read_buffer("sh.sh");
  ASSERT_EQ(bytes.size(), 9u * 16);
  std::vector<float> values(bytes.size() / 4);
  std::memcpy(values.data(), bytes.data(), bytes.size());
  for (int i = 0; i < 9; ++i) {
    const float want[4] = {float(i), 3, 0, 1};
    EXPECT_EQ(std::memcmp(&values[i * 4], want, sizeof want), 0) << "coefficient " << i;
  }
  EXPECT_THROW(exec->read_image("sh.sh"), ExecutorError);
  EXPECT_TRUE(exec->output_names().empty()) << "a file output is not an output node";
}

TEST_F(ExecTest, ANodeWithoutAKernelIsAnErrorAtConstruction) {
  KernelRegistry partial;
  partial.add("test.add", [](const PlanNode&) { return std::make_unique<NodeKernelStub>(); });
  Plan plan = compile_test_graph(context(), R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "light", "type": "test.fill" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "light.color", "to": "out.color" } ] })");
  try {
    Executor exec(context(), partial, std::move(plan));
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_STREQ(e.what(), "node 'light' (test.fill) has no kernel in this build");
  }
}

TEST_F(ExecTest, AKernelsErrorNamesThePass) {
  auto exec = executor(R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "boom", "type": "test.boom" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "boom.color", "to": "out.color" } ] })");
  GpuScene gpu_scene(context());
  try {
    exec->run_frame(scene, gpu_scene);
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_STREQ(e.what(), "pass 'boom/explode': the shader is missing");
  }
  EXPECT_EQ(exec->frames_run(), 0u) << "a failed frame does not count";
}

TEST_F(ExecTest, AnUnknownSlotNamesTheNodeAndWhatThePassBinds) {
  KernelRegistry registry;
  struct WrongSlot : NodeKernel {
    void record(PassContext& pc) override {
      EXPECT_TRUE(pc.has("out.color"));
      EXPECT_FALSE(pc.has("out.colour"));
      pc.image("out.colour");
    }
  };
  registry.add("test.fill", [](const PlanNode&) { return std::make_unique<WrongSlot>(); });
  Executor exec(context(), registry, compile_test_graph(context(), R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "f", "type": "test.fill" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "f.color", "to": "out.color" } ] })"));
  GpuScene gpu_scene(context());
  try {
    exec.run_frame(scene, gpu_scene);
    ADD_FAILURE() << "no throw";
  } catch (const ExecutorError& e) {
    EXPECT_STREQ(e.what(),
                 "pass 'f/fill': node 'f' (test.fill) has no image at 'out.colour' in this pass; it binds "
                 "out.color");
  }
}

TEST_F(ExecTest, DeviceMemoryMatchesThePlan) {
  const uint64_t before = context().device_memory_used();
  auto exec = executor(aliased_graph);
  const uint64_t used = context().device_memory_used() - before;
  const uint64_t planned = exec->plan().memory.transient + exec->plan().memory.persistent;
  EXPECT_GE(used, planned * 9 / 10);
  EXPECT_LE(used, planned * 11 / 10) << used << " bytes used, " << planned << " planned";
  GpuScene gpu_scene(context());
  FrameStats stats = exec->run_frame(scene, gpu_scene);
  EXPECT_EQ(stats.plan_memory.transient, exec->plan().memory.transient);
  EXPECT_GE(stats.device_memory_used, used);
}

TEST_F(ExecTest, StatsNameSkippedNodesAndWriteJsonAndText) {
  auto exec = executor(R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "bake", "type": "test.bake" }, { "id": "noop", "type": "test.add", "params": { "add": 0 } },
               { "id": "unused", "type": "test.fill" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "bake.color", "to": "noop.src" }, { "from": "noop.color", "to": "out.color" } ] })");
  GpuScene gpu_scene(context());
  exec->run_frame(scene, gpu_scene);
  FrameStats stats = exec->run_frame(scene, gpu_scene);
  ASSERT_EQ(stats.skipped_nodes.size(), 2u);
  EXPECT_EQ(stats.skipped_nodes[0].id, "noop");
  EXPECT_EQ(stats.skipped_nodes[0].state, NodeState::Kind::bypassed);
  EXPECT_EQ(stats.skipped_nodes[0].reason, "adds nothing");
  EXPECT_EQ(stats.skipped_nodes[1].id, "unused");
  EXPECT_EQ(stats.skipped_nodes[1].state, NodeState::Kind::culled);
  EXPECT_GE(stats.gpu_ms, 0.0);

  const JsonValue json = frame_stats_json(stats);
  EXPECT_EQ(json.find("format")->as_string(), "lumagraph-frame-stats/1");
  EXPECT_EQ(json.find("frame")->as_number(), 1);
  const JsonValue& pass = json.find("passes")->items().at(0);
  EXPECT_EQ(pass.find("name")->as_string(), "bake/fill");
  EXPECT_TRUE(pass.find("cached")->as_bool());
  EXPECT_EQ(json.find("skipped_nodes")->items().at(0).find("state")->as_string(), "bypassed");
  EXPECT_EQ(json.find("memory")->find("transient_bytes")->as_number(), double(stats.plan_memory.transient));

  const std::string text = frame_stats_text(stats);
  EXPECT_NE(text.find("bake/fill                   cached"), std::string::npos) << text;
  EXPECT_NE(text.find("bypassed:\n  noop (test.add): adds nothing\n"), std::string::npos) << text;
  EXPECT_NE(text.find("culled:\n  unused (test.fill): "), std::string::npos) << text;
}

TEST_F(ExecTest, StatsNameDroppedPasses) {
  SceneSummary no_area_lights = default_scene_summary();
  no_area_lights.sphere_lights = no_area_lights.tube_lights = 0;
  Executor exec(context(), kernels.registry,
                compile_test_graph(context(), R"({ "format": "lumagraph/1",
    "nodes": [ { "id": "light", "type": "test.lit" }, { "id": "out", "type": "test.display" } ],
    "links": [ { "from": "light.color", "to": "out.color" } ] })",
                                   true, {width, height}, no_area_lights));
  GpuScene gpu_scene(context());
  FrameStats stats = exec.run_frame(scene, gpu_scene);
  ASSERT_EQ(stats.passes.size(), 1u);
  EXPECT_EQ(stats.passes[0].name, "light/direct");
  ASSERT_EQ(stats.dropped_passes.size(), 1u);
  EXPECT_EQ(stats.dropped_passes[0].pass, "light/area");
  EXPECT_EQ(stats.dropped_passes[0].type, "test.lit");
  EXPECT_FALSE(stats.dropped_passes[0].reason.empty());
  EXPECT_NE(frame_stats_text(stats).find("passes dropped:\n  light/area (test.lit): " + stats.dropped_passes[0].reason),
            std::string::npos);
  EXPECT_EQ(wrong_texels(exec.read_image("light.color"), filled(0.75f)), 0);
}

TEST_F(ExecTest, RunsOnADeviceAdoptedFromAHost) {
  Context host(HostDevice{context().instance(), context().physical_device(), context().device(), context().queue(),
                          context().queue_family()});
  ASSERT_FALSE(host.owns_device());
  Executor exec(host, kernels.registry, compile_test_graph(host, chain_graph));
  GpuScene gpu_scene(host);
  for (int frame = 0; frame < 2; ++frame) {
    exec.run_frame(scene, gpu_scene);
    EXPECT_EQ(wrong_texels(exec.read_image("two.color"), filled(3.25f)), 0);
  }
}

}  // namespace
}  // namespace lg::test
