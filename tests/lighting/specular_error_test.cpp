// debiased_specular_error on synthetic frames with a known truth: two references are the truth
// plus independent noise, much larger than the frame's error, as a path-traced reference's is.
#include <gtest/gtest.h>

#include <random>

#include "runtime/scene/scene_file.h"
#include "tests/lighting/captured_reflection_mask.h"
#include "tests/lighting/specular_error.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 200, kHeight = 100;
constexpr size_t kPixels = size_t(kWidth) * kHeight;

// The truth is 1 in every channel; the reference adds normal noise of `sigma` from `seed`.
ReferenceImage noisy_reference(float sigma, uint32_t seed) {
  ReferenceImage r;
  r.width = kWidth, r.height = kHeight, r.row_begin = 0, r.row_end = kHeight;
  std::mt19937 random(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  for (auto& aov : r.mean) aov.assign(kPixels, glm::vec3(1.0f));
  for (auto& aov : r.standard_error) aov.assign(kPixels, glm::vec3(sigma));
  for (glm::vec3& v : r.mean[size_t(ReferenceAov::specular)]) v += glm::vec3(noise(random), noise(random), noise(random));
  return r;
}

// A frame whose specular term (lit less direct) is the truth times (1 + error) everywhere, on metal.
struct Frame {
  std::vector<float> lit, direct, material;
};
Frame frame_with_error(float error) {
  Frame f{std::vector<float>(4 * kPixels, 1.0f + error), std::vector<float>(4 * kPixels, 0.0f),
          std::vector<float>(4 * kPixels, 0.0f)};
  for (size_t i = 0; i < kPixels; ++i) f.material[4 * i + 1] = 1.0f;  // metalness
  return f;
}

DebiasedError measure(const Frame& f, const ReferenceImage& a, const ReferenceImage& b) {
  return debiased_specular_error(a, b, f.lit, f.direct, f.material, {});
}

TEST(SpecularError, DebiasedRmsRecoversTheErrorUnderAReferenceNoisierThanIt) {
  // Reference noise 0.3 a trace (0.21 for their mean) against frame errors of 0.1 and 0.2.
  const ReferenceImage a = noisy_reference(0.3f, 1), b = noisy_reference(0.3f, 2);
  const DebiasedError small = measure(frame_with_error(0.1f), a, b);
  const DebiasedError large = measure(frame_with_error(0.2f), a, b);
  EXPECT_EQ(small.pixels, kPixels);
  // The estimate's standard deviation over 60,000 values is about 0.002 at 0.1 and 0.001 at 0.2
  // (the cross term's variance is about error^2 2 sigma^2 + sigma^4): 3 of them allowed.
  EXPECT_NEAR(small.rms, 0.1, 0.006);
  EXPECT_NEAR(large.rms, 0.2, 0.004);
  EXPECT_NEAR(small.noise_rms, 0.3 / std::sqrt(2.0), 0.005);
  // With the noise in, the plain RMS is sqrt(error^2 + 0.045) and the ratio of the two errors
  // shrinks from 2 to about 1.3; debiased, it stays 2.
  EXPECT_NEAR(small.plain_rms, std::sqrt(0.01 + 0.045), 0.005);
  EXPECT_LT(large.plain_rms / small.plain_rms, 1.4);
  EXPECT_NEAR(large.rms / small.rms, 2.0, 0.15);
}

TEST(SpecularError, DebiasedRmsIsTheRmsErrorAgainstANoiselessReference) {
  const ReferenceImage exact = noisy_reference(0.0f, 1);
  const DebiasedError e = measure(frame_with_error(0.25f), exact, exact);
  EXPECT_NEAR(e.rms, 0.25, 1e-6);
  EXPECT_NEAR(e.plain_rms, 0.25, 1e-6);
  EXPECT_EQ(e.noise_rms, 0.0);
}

TEST(SpecularError, DebiasedRmsIsZeroNotNaNWhereTheNoiseOutweighsTheError) {
  // A perfect frame: the cross term's mean is 0 +- sigma^2 / sqrt(60,000) = 0.00037, negative
  // half the time (clamped to 0); its square root is then at most sqrt(3 x 0.00037) = 0.033 at 3
  // standard deviations, against 0.21 for the plain RMS.
  const ReferenceImage a = noisy_reference(0.3f, 3), b = noisy_reference(0.3f, 4);
  const DebiasedError e = measure(frame_with_error(0.0f), a, b);
  EXPECT_TRUE(std::isfinite(e.rms));
  EXPECT_LT(e.rms, 0.035);
  EXPECT_GT(e.plain_rms, 0.2);
}

TEST(SpecularError, AveragedReferencesHalveTheVarianceOfTheirMean) {
  const ReferenceImage a = noisy_reference(0.3f, 5), b = noisy_reference(0.3f, 6);
  const ReferenceImage m = average_references(a, b);
  EXPECT_FLOAT_EQ(m.mean_of(ReferenceAov::specular)[7].x,
                  0.5f * (a.mean_of(ReferenceAov::specular)[7].x + b.mean_of(ReferenceAov::specular)[7].x));
  EXPECT_NEAR(m.error_of(ReferenceAov::specular)[7].y, 0.3 / std::sqrt(2.0), 1e-6);
  const SpecularError e = specular_error(m, frame_with_error(0.0f).lit, frame_with_error(0.0f).direct,
                                         frame_with_error(0.0f).material, {});
  // Mean |N(0, 0.3 / sqrt 2)| = 0.212 sqrt(2 / pi) = 0.169; 60,000 values, so within 0.003.
  EXPECT_NEAR(e.relative, 0.3 / std::sqrt(2.0) * std::sqrt(2.0 / M_PI), 0.003);
}

// A mirror floor seen from above at 45 degrees, a ball left out of the captures standing on it
// in the middle of the view: the floor pixels in front of the ball mirror it, those at the image's
// sides mirror the open sky.
TEST(CapturedReflectionMask, FloorPixelsMirroringAnUncapturedBallAreLeftOut) {
  const World world = parse_scene_file(R"({
    "format": "lumagraph-world/1",
    "materials": {"steel": {"roughness": 0.1, "metalness": 1}},
    "entities": [
      {"name": "floor", "shape": {"type": "quad", "size": [20, 20]}, "material": "steel"},
      {"name": "ball", "transform": {"position": [0, 0.5, 0]}, "shape": {"type": "sphere", "radius": 0.5},
       "captured_by_probes": false},
      {"name": "camera", "transform": {"position": [0, 3, 3], "look_at": [0, 0, 0]}, "camera": {"vertical_fov": 60}}
    ]})", "mask-test.json");
  const uint32_t w = 64, h = 48;
  const std::vector<uint8_t> mask = captured_reflection_mask(world, w, h, 0.01f);
  // Row 28 looks 6.2 degrees below the centre (the ball covers 2.2 below to 12.6 above): the floor
  // just in front of the ball, z = 0.59, whose mirror ray (51 degrees up, back) passes 0.16 from the
  // ball's centre. Row 36, 15 degrees below, sees z = 1.27, whose mirror ray passes 2.2 m up over
  // the ball into the sky.
  size_t left_out = 0;
  for (uint8_t m : mask) left_out += m == 0;
  EXPECT_EQ(mask[28 * w + w / 2], 0) << "the floor in front of the ball mirrors it";
  EXPECT_EQ(mask[36 * w + w / 2], 1) << "the floor nearer the camera mirrors the sky";
  EXPECT_GT(left_out, 20u);
  EXPECT_LT(left_out, size_t(w) * h / 2);
  // With the ball captured, nothing is left out but the pixels where the camera sees no surface.
  World captured = parse_scene_file(R"({
    "format": "lumagraph-world/1",
    "materials": {"steel": {"roughness": 0.1, "metalness": 1}},
    "entities": [
      {"name": "floor", "shape": {"type": "quad", "size": [20, 20]}, "material": "steel"},
      {"name": "ball", "transform": {"position": [0, 0.5, 0]}, "shape": {"type": "sphere", "radius": 0.5}},
      {"name": "camera", "transform": {"position": [0, 3, 3], "look_at": [0, 0, 0]}, "camera": {"vertical_fov": 60}}
    ]})", "mask-test.json");
  const std::vector<uint8_t> all = captured_reflection_mask(captured, w, h, 0.01f);
  EXPECT_EQ(all[28 * w + w / 2], 1);
}

}  // namespace
}  // namespace lg::test
