// The camera jitter of temporal anti-aliasing (runtime/scene/camera_jitter.h): the Halton
// sequence against its definition, the 16 frames' samples covering the pixel around its centre,
// and the jittered projection moving every point by the jitter in NDC while no jitter changes
// no bit.
#include "runtime/scene/camera_jitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "runtime/scene/projection.h"

namespace lg {
namespace {

TEST(CameraJitter, HaltonIsTheRadicalInverse) {
  // Index i written in base b, its digits mirrored behind the point: exact in binary doubles
  // for base 2, within one rounding for base 3.
  EXPECT_EQ(halton(1, 2), 0.5);
  EXPECT_EQ(halton(2, 2), 0.25);
  EXPECT_EQ(halton(3, 2), 0.75);
  EXPECT_EQ(halton(6, 2), 0.375);  // 110 -> 0.011
  EXPECT_NEAR(halton(1, 3), 1.0 / 3, 1e-15);
  EXPECT_NEAR(halton(5, 3), 2.0 / 3 + 1.0 / 9, 1e-15);  // 12 -> 0.21
  EXPECT_EQ(halton(0, 3), 0.0);
}

// Sixteen frames of jitter stay within the pixel, repeat, and average near its centre: their
// mean is off by 1/32 of a pixel at most in x (Halton 2's 16th sample) and 0.05 in y, which is
// what 16 points of the sequence give; no two are alike.
TEST(CameraJitter, SequenceCoversThePixelAroundItsCentre) {
  glm::vec2 sum(0.0f);
  for (uint32_t i = 0; i < kJitterSequenceLength; ++i) {
    const glm::vec2 j = frame_jitter_pixels(i);
    EXPECT_GE(j.x, -0.5f);
    EXPECT_LT(j.x, 0.5f);
    EXPECT_GE(j.y, -0.5f);
    EXPECT_LT(j.y, 0.5f);
    EXPECT_EQ(frame_jitter_pixels(i + kJitterSequenceLength), j);
    for (uint32_t k = 0; k < i; ++k) EXPECT_NE(frame_jitter_pixels(k), j) << k << " and " << i;
    sum += j;
  }
  EXPECT_LE(std::abs(sum.x / float(kJitterSequenceLength)), 1.0f / 32 + 1e-6f);
  EXPECT_LE(std::abs(sum.y / float(kJitterSequenceLength)), 0.05f);
}

TEST(CameraJitter, ProjectionMovesByTheJitterAndNotAtAllWithout) {
  CameraView camera;
  camera.projection = reversed_z_infinite_perspective(0.9f, 16.0f / 9.0f, 0.05f);
  const glm::mat4 still = jittered_projection(camera);
  EXPECT_EQ(std::memcmp(&still, &camera.projection, sizeof still), 0);

  camera.jitter = jitter_ndc({0.25f, -0.375f}, 160, 90);
  EXPECT_FLOAT_EQ(camera.jitter->x, 2.0f * 0.25f / 160.0f);
  EXPECT_FLOAT_EQ(camera.jitter->y, -2.0f * 0.375f / 90.0f);
  const glm::mat4 moved = jittered_projection(camera);
  for (glm::vec4 p : {glm::vec4(0.3f, -0.2f, -1.0f, 1.0f), glm::vec4(-4.0f, 2.0f, -30.0f, 1.0f)}) {
    const glm::vec4 a = camera.projection * p, b = moved * p;
    // NDC moves by the jitter, depth does not: 1e-6 is float rounding at these magnitudes.
    EXPECT_NEAR(b.x / b.w - a.x / a.w, camera.jitter->x, 1e-6f);
    EXPECT_NEAR(b.y / b.w - a.y / a.w, camera.jitter->y, 1e-6f);
    EXPECT_FLOAT_EQ(b.z / b.w, a.z / a.w);
  }
}

}  // namespace
}  // namespace lg
