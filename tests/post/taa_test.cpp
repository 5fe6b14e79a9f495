// post.taa on lavapipe with validation on: the camera jitter reaches the plan and the G-buffer
// while the motion vectors leave it out, the static-camera convergence claim of issue 19 against
// the 64-sample supersampled reference, history restarts on a camera cut and a resize, and
// non-finite or extreme input never reaching the output or the history.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "graph/compiler.h"
#include "nodes/builtin_schemas.h"
#include "runtime/scene/default_world.h"
#include "tests/post/exposure_harness.h"
#include "tests/post/taa_support.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kSmall{96, 54};

bool all_finite(const std::vector<float>& v) {
  return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
}

TEST(Taa, PlanJittersTheCameraOnTheColourInputsGrid) {
  for (bool taa : {false, true}) {
    Diagnostics d("taa-test.json");
    CompileOptions options;
    options.frame = {96, 54};
    CompileResult result = compile(taa_test_graph(taa), builtin_registry(), options, d);
    ASSERT_TRUE(result.plan) << d.to_string();
    const std::array<uint32_t, 2> expected = taa ? std::array<uint32_t, 2>{96, 54} : std::array<uint32_t, 2>{0, 0};
    EXPECT_EQ(result.plan->jitter_grid, expected) << (taa ? "with" : "without") << " post.taa";
  }
}

// A still camera on a still world: every motion vector is 0 although each frame's depth moved
// with the jitter. Tolerance 1e-5 in uv (a thousandth of a pixel at 96 wide): the float rounding
// of uv_now - uv_before - jitter / 2, stored in rg16f.
TEST(Taa, MotionVectorsLeaveTheJitterOut) {
  const World world = default_world();
  Renderer renderer(taa_renderer_options());
  renderer.set_graph(taa_test_graph(true));
  renderer.render(world, kSmall);
  const std::vector<float> first_depth = renderer.executor().read_image("gbuf.gbuffer.depth");
  for (int frame = 1; frame < 3; ++frame) {
    renderer.render(world, kSmall);
    const std::vector<float> motion = renderer.executor().read_image("gbuf.gbuffer.motion");
    float largest = 0.0f;
    for (size_t k = 0; k < motion.size(); k += 4)
      largest = std::max({largest, std::abs(motion[k]), std::abs(motion[k + 1])});
    EXPECT_LT(largest, 1e-5f) << "frame " << frame;
  }
  EXPECT_NE(renderer.executor().read_image("gbuf.gbuffer.depth"), first_depth) << "the jitter did not move the image";
  expect_no_validation_messages(renderer.context());
}

// Issue 19's claim: on a still camera TAA converges to at most half the unjittered frame's error
// against the supersampled reference (64 Halton samples, the jitter's own distribution). 48
// frames leave 0.9^48 = 0.6% of the first frame's weight in the history. The bound is the claim
// itself; docs/bench/taa records the measured ratio (well under it) and its change per frame.
TEST(Taa, StillCameraConvergesToHalfTheUnjitteredError) {
  const World world = default_world();
  Renderer renderer(taa_renderer_options());
  const std::vector<float> reference = supersampled_reference(renderer, world, kSmall, 64);
  renderer.render(world, kSmall);  // no post.taa: no jitter
  const double unjittered = compressed_rms_error(renderer.executor().read_image("light.color"), reference);
  renderer.set_graph(taa_test_graph(true));
  for (int frame = 0; frame < 48; ++frame) renderer.render(world, kSmall);
  const std::vector<float> taa = renderer.executor().read_image("taa.color");
  ASSERT_TRUE(all_finite(taa));
  const double error = compressed_rms_error(taa, reference);
  RecordProperty("unjittered_error", std::to_string(unjittered));
  RecordProperty("taa_error", std::to_string(error));
  EXPECT_GT(unjittered, 1e-3) << "the scene has no edges to alias: the test would prove nothing";
  EXPECT_LE(error, 0.5 * unjittered) << "TAA " << error << " against unjittered " << unjittered;
  expect_no_validation_messages(renderer.context());
}

// A resize makes a new plan whose history starts cleared: its first frame is bit for bit a
// fresh renderer's first frame at that size.
TEST(Taa, ResizeRestartsTheHistory) {
  const World world = default_world();
  const FrameSize resized{80, 45};
  Renderer renderer(taa_renderer_options());
  renderer.set_graph(taa_test_graph(true));
  for (int frame = 0; frame < 4; ++frame) renderer.render(world, kSmall);
  renderer.render(world, resized);
  Renderer fresh(taa_renderer_options());
  fresh.set_graph(taa_test_graph(true));
  fresh.render(world, resized);
  EXPECT_EQ(renderer.executor().read_image("taa.color"), fresh.executor().read_image("taa.color"));
  expect_no_validation_messages(renderer.context());
  expect_no_validation_messages(fresh.context());
}

// After a camera cut the output is this frame alone: light.color through the reversible tone map
// and back, stored as half floats (relative tolerance 2^-10, half's rounding, plus 1e-6 for the
// float round trip near 0); the frame before, with history, is not (the accumulation differs at
// the edges by far more).
TEST(Taa, CameraCutRestartsTheHistory) {
  const World world = default_world();
  Renderer renderer(taa_renderer_options());
  renderer.set_graph(taa_test_graph(true));
  auto largest_difference = [&] {
    const std::vector<float> taa = renderer.executor().read_image("taa.color");
    const std::vector<float> light = renderer.executor().read_image("light.color");
    double largest = 0.0;
    for (size_t k = 0; k < taa.size(); ++k)
      if (k % 4 != 3) largest = std::max(largest, std::abs(double(taa[k]) - light[k]) / (std::abs(light[k]) + 1e-3));
    return largest;
  };
  for (int frame = 0; frame < 6; ++frame) renderer.render(world, kSmall);
  EXPECT_GT(largest_difference(), 0.05);
  renderer.render(world, kSmall, {.camera_cut = true});
  EXPECT_LT(largest_difference(), std::ldexp(1.0, -10) + 1e-3);
  expect_no_validation_messages(renderer.context());
}

class TaaStress : public GpuTest {};

// Random HDR radiance with NaN, +-Inf, 1e30 (beyond half floats: Inf once stored), denormals and
// negative pixels in a quarter of the pixels, fed for 8 frames with a still G-buffer and sharpening
// on: the output and the history stay finite and within half float's range.
TEST_F(TaaStress, NonFiniteAndExtremeInputNeverSpreads) {
  const uint32_t w = 64, h = 36;
  HostImage image{w, h, std::vector<float>(size_t{w} * h * 4)};
  std::mt19937 random(std::random_device{}());
  std::uniform_real_distribution<float> radiance(0.0f, 4.0f);
  const float specials[] = {std::nanf(""), INFINITY, -INFINITY, 1e30f, 1e-40f, -3.0f};
  std::uniform_int_distribution<int> pick(0, 23);  // 0-5: a special value
  std::string graph = R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" },
    { "id": "gbuf", "type": "scene.gbuffer" }, { "id": "taa", "type": "post.taa", "params": { "sharpen": 0.5 } } ],
    "links": [ { "from": "src.color", "to": "taa.color" }, { "from": "gbuf.gbuffer", "to": "taa.gbuffer" },
               { "from": "taa.accumulated", "to": "taa.history" } ],
    "outputs": [ "taa.color", "taa.accumulated", "src.color" ] })";
  ExposureHarness harness(context(), graph, image);
  for (int frame = 0; frame < 8; ++frame) {
    for (size_t p = 0; p < size_t{w} * h; ++p) {
      const int kind = pick(random);
      for (int c = 0; c < 3; ++c)
        harness.image().rgba[p * 4 + c] = kind < 6 && c == kind % 3 ? specials[kind] : radiance(random);
      harness.image().rgba[p * 4 + 3] = 1.0f;
    }
    harness.run_frame();
    for (const char* resource : {"taa.color", "taa.accumulated"}) {
      const std::vector<float> out = harness.executor().read_image(resource);
      ASSERT_TRUE(all_finite(out)) << resource << " frame " << frame;
      EXPECT_LE(*std::max_element(out.begin(), out.end()), 65504.0f) << resource << " frame " << frame;
    }
  }
}

}  // namespace
}  // namespace lg::test
