// Failures injected (graph/fault_injection.h) into device allocations while the default graph
// is compiled for a new frame size and its first frame runs, into shader modules while a new
// renderer makes its pipelines (a resize reuses those of the last plan), and into hot reloads:
// the error names what failed, and the Renderer keeps its last good state, so the next frame
// renders exactly what a Renderer that never failed renders.
#include "graph/fault_injection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

#include "api/renderer.h"
#include "runtime/scene/default_world.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

const std::string kGraph = LUMAGRAPH_SOURCE_DIR "/examples/default.json";
constexpr FrameSize kSmall{64, 36}, kLarger{96, 54};
// At most this many of a site's calls are failed one by one (evenly spread, the first and the
// last among them): each try costs a frame, and a new renderer's pipelines, about a second.
constexpr uint64_t kMaxTried = 8;

// No pipeline cache on disk: every renderer makes its pipelines afresh, from the same calls.
RendererOptions test_options() {
  RendererOptions options;
  options.device.validation = true;
  options.pipeline_cache_on_disk = false;
  return options;
}

Renderer make_renderer() {
  return Renderer(test_options());
}

// The first frame at `size` of a renderer that never failed (the first frame of an executor:
// history starts empty, so it does not depend on frames before).
std::vector<float> clean_first_frame(FrameSize size) {
  Renderer renderer = make_renderer();
  renderer.load_graph(kGraph);
  renderer.render(default_world(), size);
  return renderer.read_output();
}

// Where failures are injected: a resize (a compile, a new executor and its first frame) of a
// renderer that rendered at kSmall, or the first frame of a new renderer, which also makes its
// pipelines (a resize finds them made).
enum class Scenario { resize, new_renderer };

// How many calls at `site` the scenario makes.
uint64_t calls_of(Scenario scenario, FaultSite site) {
  std::optional<Renderer> renderer;
  if (scenario == Scenario::resize) {
    renderer.emplace(test_options());
    renderer->load_graph(kGraph);
    renderer->render(default_world(), kSmall);
  }
  arm_fault(site, std::numeric_limits<uint64_t>::max());
  if (!renderer) {
    renderer.emplace(test_options());
    renderer->load_graph(kGraph);
  }
  renderer->render(default_world(), kLarger);
  const uint64_t calls = fault_site_calls(site);
  arm_fault(site, 0);
  return calls;
}

void fail_each_call(Scenario scenario, FaultSite site, const std::string& failed_call) {
  const uint64_t calls = calls_of(scenario, site);
  ASSERT_GT(calls, 0u) << "the scenario makes no call at this site, so nothing would be tested";
  const std::vector<float> small = clean_first_frame(kSmall), larger = clean_first_frame(kLarger);

  std::optional<Renderer> renderer;
  const uint64_t tried = std::min(calls, kMaxTried);
  for (uint64_t i = 0; i < tried; ++i) {
    const uint64_t nth = tried == 1 ? 1 : 1 + i * (calls - 1) / (tried - 1);
    if (scenario == Scenario::new_renderer || !renderer) {
      renderer.emplace(test_options());
      renderer->load_graph(kGraph);
      if (scenario == Scenario::resize) renderer->render(default_world(), kSmall);
    }
    // A resize alternates sizes, so every attempt builds a new executor the same way.
    const bool grow = scenario == Scenario::new_renderer || i % 2 == 0;
    SCOPED_TRACE("call " + std::to_string(nth) + " of " + std::to_string(calls) + (grow ? ", growing" : ", shrinking"));
    arm_fault(site, nth);
    try {
      renderer->render(default_world(), grow ? kLarger : kSmall);
      ADD_FAILURE() << "the injected failure did not reach the caller";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(failed_call), std::string::npos) << e.what();
    }
    arm_fault(site, 0);
    renderer->context().take_validation_messages();  // a failed frame may leave some; the next must not
    renderer->render(default_world(), grow ? kLarger : kSmall);
    EXPECT_EQ(renderer->read_output(), grow ? larger : small);
    const auto messages = renderer->context().take_validation_messages();
    EXPECT_TRUE(messages.empty()) << describe(messages);
  }
}

TEST(FaultInjection, AFailedDeviceAllocationLeavesTheRendererAbleToRenderTheNextFrame) {
  fail_each_call(Scenario::resize, FaultSite::device_allocation, "vkAllocateMemory");
}

TEST(FaultInjection, AFailedShaderModuleLeavesTheRendererAbleToRenderTheNextFrame) {
  fail_each_call(Scenario::new_renderer, FaultSite::shader_module, "vkCreateShaderModule");
}

// Hot reload: a graph file that vanished, was half written, or could not be read keeps the last
// good graph running.
TEST(FaultInjection, AReloadThatFailsKeepsTheLastGoodGraph) {
  const std::filesystem::path dir = std::filesystem::path(LUMAGRAPH_BINARY_DIR) / "test-output" / "fault-reload";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "graph.json";
  std::filesystem::copy_file(LUMAGRAPH_SOURCE_DIR "/examples/minimal.json", path,
                             std::filesystem::copy_options::overwrite_existing);
  Renderer renderer = make_renderer();
  renderer.load_graph(path.string());
  renderer.render(default_world(), kSmall);
  const std::vector<float> good = renderer.read_output();
  const size_t passes = renderer.plan().passes.size();

  const auto expect_kept = [&](const std::string& expected_error) {
    try {
      renderer.reload_graph();
      ADD_FAILURE() << "the reload succeeded";
    } catch (const GraphError& e) {
      EXPECT_NE(std::string(e.what()).find(expected_error), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
    renderer.render(default_world(), kSmall);
    EXPECT_EQ(renderer.plan().passes.size(), passes);
    EXPECT_EQ(renderer.read_output(), good);  // minimal.json keeps no history: frames repeat
  };

  arm_fault(FaultSite::file_read, 1);
  expect_kept("cannot read the file");
  arm_fault(FaultSite::file_read, 0);

  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(path, std::ios::trunc) << text.substr(0, text.size() / 2);
  expect_kept("error:");
  std::filesystem::remove(path);
  expect_kept("cannot open the file");

  std::ofstream(path) << text;  // back: the reload works again
  renderer.reload_graph();
  renderer.render(default_world(), kSmall);
  EXPECT_EQ(renderer.read_output(), good);
}

}  // namespace
}  // namespace lg::test
