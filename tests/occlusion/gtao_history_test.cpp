// occlusion.gtao's temporal accumulation restarts on a camera cut, by the rule post.taa,
// post.exposure and lighting.ssr share (nodes/common/history.h): the frame after a cut is that
// frame alone, as GTAO with temporal_blend 0 gives it at the same frame index (the horizon
// search's noise turns with the frame index, so the index must match).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "api/renderer.h"
#include "runtime/scene/default_world.h"
#include "tests/occlusion/ao_render.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr FrameSize kFrame{96, 54};

// A validating renderer of the G-buffer and GTAO (its history linked back; tests/occlusion/ao_render.h).
void use_gtao(Renderer& renderer, double temporal_blend) {
  renderer.set_graph(occlusion_graph(R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "low",
      "temporal_blend": )" + std::to_string(temporal_blend) + " } }"));
}

float largest_difference(const std::vector<float>& a, const std::vector<float>& b) {
  float largest = 0;
  for (size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

// Six frames accumulate (the still camera's history differs from the frame alone by well over
// the r8 output's step of 1/255 where the noise turns: measured up to 0.2); the seventh, a cut,
// equals the frame alone exactly: both denoise this frame's horizons and blend no history.
TEST(GtaoHistory, CameraCutRestartsTheAccumulation) {
  const World world = default_world();
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;  // every output is read back after its frame
  Renderer accumulating(options), alone(options);
  use_gtao(accumulating, 0.9);
  use_gtao(alone, 0.0);
  for (int frame = 0; frame < 6; ++frame) {
    accumulating.render(world, kFrame);
    alone.render(world, kFrame);
  }
  EXPECT_GT(largest_difference(accumulating.executor().read_image("ao.ao"), alone.executor().read_image("ao.ao")),
            4.0f / 255.0f);
  accumulating.render(world, kFrame, {.camera_cut = true});
  alone.render(world, kFrame);
  EXPECT_EQ(largest_difference(accumulating.executor().read_image("ao.ao"), alone.executor().read_image("ao.ao")),
            0.0f);
  expect_no_validation_messages(accumulating.context());
  expect_no_validation_messages(alone.context());
}

}  // namespace
}  // namespace lg::test
