// post.dof on lavapipe with validation on, over the Cornell box's G-buffer at 160x90 seen through
// a wide-open lens focused 0.5 m away (every surface and the sky defocused, circles at the
// largest blur): a constant image stays constant (the gather's weights are normalised however
// far each tap's circle reaches), and NaN and Inf texels neither spread nor pass.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/post/guided_frame.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

// rgba16f holds 11 significant bits: the gather's weighted mean of equal values and the
// composite's blend each land within a step or two of the value (bilateral_test.cpp's bound).
constexpr float kHalfFloatSteps = 1.0f / 512.0f;

class DofFinite : public GpuTest {};

// A few NaN, +Inf and -Inf texels over a constant image: every output finite, every good pixel
// the constant (bad taps weigh nothing; before, a bad tap's zero weight times Inf or NaN made
// every pixel within the largest blur NaN, which the composite wrote as black).
TEST_F(DofFinite, ConstantStaysConstantAndBadTexelsDoNotSpread) {
  const float c[4] = {3.0f, 1.5f, 0.25f, 1.0f};
  HostImage image = constant_image(kWidth, kHeight, c);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<bool> bad(size_t{kWidth} * kHeight, false);
  for (size_t i = 0; i < bad.size(); i += 997) {
    image.rgba[4 * i + i % 3] = i % 3 == 0 ? nan : i % 3 == 1 ? inf : -inf;
    bad[i] = true;
  }
  SceneSummary lens = default_scene_summary();
  lens.aperture = 1.0;
  lens.focus_distance = 0.5;
  ExposureHarness h(context(), guided_graph(R"({ "id": "node", "type": "post.dof" })"), image, std::nullopt, lens);
  show_cornell_box(h, kWidth, kHeight);
  h.scene().camera.aperture = float(lens.aperture);
  h.scene().camera.focus_distance = float(lens.focus_distance);
  h.run_frame();
  const std::vector<float> out = h.executor().read_image("node.color");
  ASSERT_EQ(out.size(), 4 * bad.size());
  size_t non_finite = 0, wrong = 0;
  for (size_t i = 0; i < bad.size(); ++i) {
    for (int ch = 0; ch < 4; ++ch) non_finite += std::isfinite(out[4 * i + ch]) ? 0 : 1;
    if (bad[i]) continue;
    for (int ch = 0; ch < 3; ++ch)
      if (!(std::abs(out[4 * i + ch] - c[ch]) <= kHalfFloatSteps * c[ch])) ++wrong;
  }
  EXPECT_EQ(non_finite, 0u);
  EXPECT_EQ(wrong, 0u);
}

}  // namespace
}  // namespace lg::test
