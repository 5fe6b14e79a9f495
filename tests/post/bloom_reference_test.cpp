// post.bloom against the direct convolution with its stated kernel (tests/post/bloom_reference.h),
// intensity 1 and threshold 0, so that its output is the bloom term itself. The energy test is
// beside the example renders (tests/render/examples_test.cpp).
#include "tests/post/bloom_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "runtime/gpu/context.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

std::string bloom_graph(uint32_t levels) {
  return R"({ "format": "lumagraph/1", "nodes": [ { "id": "src", "type": "test.image" },
    { "id": "bloom", "type": "post.bloom", "params": { "intensity": 1, "threshold": 0, "levels": )" +
         std::to_string(levels) + R"( } } ],
    "links": [ { "from": "src.color", "to": "bloom.color" } ], "outputs": [ "bloom.color" ] })";
}

Context& context() {
  static Context c{ContextOptions{.validation = true}};
  return c;
}

HostImage black(uint32_t width, uint32_t height) {
  return {width, height, std::vector<float>(size_t{width} * height * 4, 0.0f)};
}

// The chain's response to an impulse, averaged over the impulse's 4 x 4 positions against the
// coarsest grid of 2 levels (one texel in 4 pixels), is the stated kernel itself: that is how the
// kernel is derived. Only the rgba16f levels differ (2^-11 relative): 1e-3 of the peak.
TEST(BloomReference, TheChainsPhaseAveragedImpulseResponseIsTheKernel) {
  constexpr uint32_t kSize = 64, kLevels = 2;
  ExposureHarness h(context(), bloom_graph(kLevels), black(kSize, kSize));
  std::vector<double> mean(size_t{kSize} * kSize, 0.0);
  constexpr int kCentre = 28;
  for (int py = 0; py < 4; ++py)
    for (int px = 0; px < 4; ++px) {
      h.image() = black(kSize, kSize);
      h.image().rgba[(size_t(kCentre + py) * kSize + kCentre + px) * 4] = 1.0f;
      h.run_frame();
      const std::vector<float> out = h.executor().read_image("bloom.color");
      for (int y = 0; y + py < int(kSize); ++y)
        for (int x = 0; x + px < int(kSize); ++x)
          mean[size_t(y) * kSize + x] += out[(size_t(y + py) * kSize + x + px) * 4] / 16.0;
    }
  std::vector<std::vector<double>> k;
  for (uint32_t l = 0; l < kLevels; ++l) k.push_back(bloom_level_kernel(l));
  double peak = 0, worst = 0, total = 0;
  for (int y = 0; y < int(kSize); ++y)
    for (int x = 0; x < int(kSize); ++x) {
      double expected = 0;
      for (const auto& kl : k) {
        const int r = int(kl.size() / 2), dx = x - kCentre + r, dy = y - kCentre + r;
        if (dx >= 0 && dy >= 0 && dx < int(kl.size()) && dy < int(kl.size())) expected += kl[dx] * kl[dy] / kLevels;
      }
      peak = std::max(peak, expected);
      total += mean[size_t(y) * kSize + x];
      worst = std::max(worst, std::abs(mean[size_t(y) * kSize + x] - expected));
    }
  std::printf("phase-averaged impulse: largest difference %.3g of a peak of %.4f; total %.5f\n", worst, peak, total);
  EXPECT_LT(worst, 1e-3 * peak);
  EXPECT_NEAR(total, 1.0, 1e-3);
  auto messages = context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << describe(messages);
}

// On random radiance (values in [0, 1], one texel in a hundred 300 times brighter) what is left is
// the chain's shift variance: each bright texel goes down the chain at one phase against each
// level's grid, not averaged over all, so its bloom is the kernel shifted and reshaped by up to
// a texel of the level. That is most of the error, and most of the image's light is in the bright
// texels: measured 17.3 to 18.6% relative RMS over six seeds; 22% is the bound. The totals agree
// to the rgba16f chain's rounding (measured 0.16% low). The image keeps 40 pixels of black around
// its content, farther than the 3-level kernel reaches, so the clamped edges play no part.
TEST(BloomReference, MatchesTheDirectConvolutionOnRandomRadiance) {
  constexpr uint32_t kWidth = 192, kHeight = 128, kLevels = 3, kMargin = 40;
  std::mt19937 rng(1);  // a fixed image: a failure is the same on every run
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  HostImage image = black(kWidth, kHeight);
  for (uint32_t y = kMargin; y < kHeight - kMargin; ++y)
    for (uint32_t x = kMargin; x < kWidth - kMargin; ++x)
      for (int c = 0; c < 3; ++c)
        image.rgba[(size_t(y) * kWidth + x) * 4 + c] = uniform(rng) * (uniform(rng) < 0.01f ? 300.0f : 1.0f);
  ASSERT_GT(bloom_level_kernel(kLevels - 1).size() / 2, 20u);
  ASSERT_LT(bloom_level_kernel(kLevels - 1).size() / 2, kMargin);

  ExposureHarness h(context(), bloom_graph(kLevels), image);
  h.run_frame();
  const std::vector<float> gpu = h.executor().read_image("bloom.color");
  const HostImage reference = bloom_reference(image, kLevels);
  double difference = 0, norm = 0, gpu_total = 0, reference_total = 0;
  for (size_t k = 0; k < gpu.size(); ++k) {
    if (k % 4 == 3) continue;
    difference += std::pow(double(gpu[k]) - reference.rgba[k], 2);
    norm += std::pow(double(reference.rgba[k]), 2);
    gpu_total += gpu[k], reference_total += reference.rgba[k];
  }
  const double relative_rms = std::sqrt(difference / norm);
  std::printf("relative RMS %.4f, total %.5f of the reference's\n", relative_rms,
              gpu_total / reference_total);
  EXPECT_LT(relative_rms, 0.22);
  EXPECT_NEAR(gpu_total / reference_total, 1.0, 0.002);
  auto messages = context().take_validation_messages();
  EXPECT_TRUE(messages.empty()) << describe(messages);
}

}  // namespace
}  // namespace lg::test
