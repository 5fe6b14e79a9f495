// post.upsample on lavapipe with validation on: a smooth function sampled at half and at a
// quarter of the Cornell box's 160x90 G-buffer comes back within a bound derived from its
// slope everywhere (each pixel is a convex blend of the 2x2 texels around it) and within a
// measured tolerance on average; NaN and Inf texels never spread; an input that is not the
// G-buffer's size over a whole number is refused naming the node.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "tests/post/guided_frame.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

// The frame is the half-resolution image's size; the G-buffer draws at twice it.
constexpr uint32_t kFrameWidth = 80, kFrameHeight = 45, kWidth = 160, kHeight = 90;
constexpr const char* kNode = R"({ "id": "node", "type": "post.upsample" })";

// The kWidth x kHeight RGBA result.
std::vector<float> upsample(Context& context, const HostImage& low, double image_scale) {
  ExposureHarness h(context, guided_graph(kNode, image_scale, 2), low, FrameSize{kFrameWidth, kFrameHeight});
  show_cornell_box(h, kFrameWidth, kFrameHeight);
  h.run_frame();
  return h.executor().read_image("node.color");
}

// rgba16f rounds the image on the way in and the result on the way out: values in [1, 2]
// move by up to half of 2^-10 each time.
constexpr double kRounding = 1.0 / 1024.0;

// The bad-input checks are methods that one test runs: every test process pays seconds of
// Vulkan and validation-layer start-up on lavapipe while the checks take milliseconds.
class Upsample : public GpuTest {
 protected:
  void nan_and_inf_never_spread();
  void wrong_size_is_refused();
};

// Texel i holds the function at the G-buffer pixel it stands for, k i. A pixel blends texels
// at most D pixels away in each direction (k inside the image; at the last row or column, the
// pixels past k (texels - 1) up to the edge), so it is within D_x |f_x| + D_y |f_y| of its own
// value whatever the weights; bilinear weights on a plane come much closer. Measured on
// lavapipe (mean absolute error over all pixels; largest, bound): k = 2 0.0012 (0.031, 0.065),
// k = 4 0.0065 (0.100, 0.147); the mean's tolerances, 0.002 and 0.01, are about half again.
TEST_F(Upsample, ASmoothFunctionComesBackWithinItsTolerance) {
  struct Case {
    int k;
    double image_scale, mean_tolerance;
  };
  for (const Case& c : {Case{2, 1.0, 0.002}, Case{4, 0.5, 0.01}}) {
    const HostImage low = smooth_low_image(c.k, kWidth, kHeight);
    const std::vector<float> out = upsample(context(), low, c.image_scale);
    ASSERT_EQ(out.size(), size_t{kWidth} * kHeight * 4);
    const double reach_x = std::max<double>(c.k, kWidth - 1 - c.k * (low.width - 1));
    const double reach_y = std::max<double>(c.k, kHeight - 1 - c.k * (low.height - 1));
    const Slope slope = smooth_slope(kWidth, kHeight);
    const double bound = reach_x * slope.x + reach_y * slope.y + kRounding;
    const SmoothError e = smooth_error(out, kWidth, kHeight);
    std::printf("k = %d: mean absolute error %.5f, largest %.5f (bound %.5f)\n", c.k, e.mean, e.largest, bound);
    EXPECT_LT(e.largest, bound) << "k = " << c.k;
    EXPECT_LT(e.mean, c.mean_tolerance) << "k = " << c.k;
  }
}

// NaN, +Inf and -Inf texels count as 0: every output is finite, and a pixel whose 2x2 texels
// are all finite is the constant.
void Upsample::nan_and_inf_never_spread() {
  const float c[4] = {2.0f, 0.5f, 8.0f, 1.0f};
  HostImage low = constant_image(kFrameWidth, kFrameHeight, c);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<bool> bad(size_t{kFrameWidth} * kFrameHeight, false);
  for (size_t i = 0; i < bad.size(); ++i)
    if (i % 7 == 0 || i % 11 == 0 || i % 23 == 0) {
      low.rgba[4 * i + i % 4] = i % 7 == 0 ? nan : i % 11 == 0 ? inf : -inf;
      bad[i] = true;
    }
  const std::vector<float> out = upsample(context(), low, 1.0);
  size_t non_finite = 0, wrong = 0, clean = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const size_t i = 4 * (size_t(y) * kWidth + x);
      for (int ch = 0; ch < 4; ++ch) non_finite += std::isfinite(out[i + ch]) ? 0 : 1;
      const uint32_t lx = std::min(x / 2, kFrameWidth - 1), ly = std::min(y / 2, kFrameHeight - 1);
      bool taps_clean = true;
      for (uint32_t t = 0; t < 4; ++t)
        taps_clean &=
            !bad[size_t(std::min(ly + t / 2, kFrameHeight - 1)) * kFrameWidth + std::min(lx + t % 2, kFrameWidth - 1)];
      if (!taps_clean) continue;
      ++clean;
      for (int ch = 0; ch < 4; ++ch)
        if (std::abs(out[i + ch] - c[ch]) > kRounding * c[ch]) ++wrong;
    }
  EXPECT_EQ(non_finite, 0u);
  EXPECT_GT(clean, 1000u);
  EXPECT_EQ(wrong, 0u);
}

void Upsample::wrong_size_is_refused() {
  const float c[4] = {1, 1, 1, 1};
  ExposureHarness h(context(), guided_graph(kNode, 1.0, 1.5), constant_image(kFrameWidth, kFrameHeight, c));
  show_cornell_box(h, kFrameWidth, kFrameHeight);
  const std::string error = frame_error(h);
  EXPECT_NE(error.find("post.upsample 'node': input 'color' is 80x45 and the G-buffer that guides it "
                       "120x67; expected it at the G-buffer's size over a whole number"),
            std::string::npos)
      << error;
}

TEST_F(Upsample, BadInputNeitherSpreadsNorPasses) {
  nan_and_inf_never_spread();
  wrong_size_is_refused();
}

}  // namespace
}  // namespace lg::test
