// GTAO and SSAO on what real content throws at screen-space occlusion: thin geometry, depth
// discontinuities, pixels at the far plane, grazing views and a camera inside geometry. The
// occlusion (first frame and after GTAO's temporal accumulation; GTAO at full, half and quarter
// resolution) and GTAO's bent normals must stay finite and in range, with no validation message.
// 96x54 frames: the cases are about geometry, not resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ao_render.h"
#include "tests/occlusion/occlusion_worlds.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 96, kHeight = 54;

struct Case {
  const char* name;
  World world;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"thin plate and pole", WorldBuilder()
                                            .add(make_quad(20.0f, 20.0f), {})
                                            .add(make_box({2.0f, 1.0f, 0.001f}), {0.0f, 0.5f, -2.0f}, 30.0f)
                                            .add(make_box({0.005f, 1.5f, 0.005f}), {0.6f, 0.75f, -1.5f})
                                            .camera({0.0f, 1.0f, 1.0f}, {0.0f, 0.4f, -2.0f})
                                            .world()});
  out.push_back({"depth discontinuities", WorldBuilder()
                                              .add(make_quad(200.0f, 200.0f), {})
                                              .add(make_box({0.3f, 0.3f, 0.3f}), {0.0f, 1.2f, -0.8f})
                                              .add(make_box({0.2f, 2.0f, 0.2f}), {-0.4f, 1.0f, -40.0f})
                                              .camera({0.0f, 1.5f, 0.0f}, {0.0f, 1.0f, -3.0f})
                                              .world()});
  out.push_back({"far plane", WorldBuilder()
                                  .add(make_sphere(0.3f), {0.0f, 0.3f, -3.0f})
                                  .camera({0.0f, 0.4f, 0.0f}, {0.0f, 0.6f, -3.0f})
                                  .world()});
  out.push_back({"grazing view", WorldBuilder()
                                     .add(make_quad(400.0f, 400.0f), {})
                                     .add(make_box({1.0f, 0.05f, 1.0f}), {0.0f, 0.025f, -5.0f})
                                     .camera({0.0f, 0.01f, 0.0f}, {0.0f, 0.0f, -10.0f}, 50.0f, 0.005f)
                                     .world()});
  out.push_back({"camera inside geometry", WorldBuilder()
                                               .add(make_quad(20.0f, 20.0f), {})
                                               .add(make_box({1.0f, 1.0f, 1.0f}), {0.0f, 1.0f, 0.0f})
                                               .add(make_sphere(0.5f), {0.0f, 1.0f, -0.2f})
                                               .camera({0.0f, 1.0f, 0.0f}, {0.3f, 0.7f, -1.0f})
                                               .world()});
  return out;
}

void expect_in_range(const std::vector<float>& rgba, const std::string& what) {
  size_t bad = 0;
  for (size_t i = 0; i < rgba.size(); i += 4)
    if (!(rgba[i] >= 0.0f && rgba[i] <= 1.0f)) ++bad;  // NaN fails both
  EXPECT_EQ(bad, 0u) << what << ": occlusion outside [0, 1] or not finite";
}

void expect_bent_normals_finite(const std::vector<float>& rgba, const std::string& what) {
  size_t bad = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) {
    const float len2 = rgba[i] * rgba[i] + rgba[i + 1] * rgba[i + 1] + rgba[i + 2] * rgba[i + 2];
    // Unit vectors in rgba8_snorm come back to within 1.5% of unit length (or 0, for no surface).
    if (!std::isfinite(len2) || len2 > 1.03f || !(rgba[i + 3] >= 0.0f && rgba[i + 3] <= 1.0f)) ++bad;
  }
  EXPECT_EQ(bad, 0u) << what << ": bent normal or cone out of range";
}

constexpr const char* kGtao = R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high" } })";
// Below full resolution the upsample decides every silhouette pixel, and a pixel whose taps are
// all sky (the pole, thinner than a texel) must still come out finite. At 0.25 the 54 rows do
// not divide by 4: the last row of texels covers the remainder.
constexpr const char* kGtaoHalf =
    R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "resolution_scale": 0.5 } })";
constexpr const char* kGtaoQuarter =
    R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "resolution_scale": 0.25 } })";
constexpr const char* kSsao = R"({ "id": "ao", "type": "occlusion.ssao", "params": { "samples": 16 } })";

void expect_gtao_finite_and_in_range(const char* node) {
  for (const Case& c : cases()) {
    const AoRender r = render_occlusion(c.world, kWidth, kHeight, node, {.frames = 4});
    EXPECT_EQ(r.validation_messages, 0u) << c.name;
    expect_in_range(r.first_ao, std::string(c.name) + ", first frame");
    expect_in_range(r.last_ao, std::string(c.name) + ", after 4 frames");
    expect_bent_normals_finite(r.bent_normals, c.name);
  }
}

TEST(OcclusionStress, GtaoStaysFiniteAndInRange) {
  expect_gtao_finite_and_in_range(kGtao);
}

TEST(OcclusionStress, GtaoAtHalfResolutionStaysFiniteAndInRange) {
  expect_gtao_finite_and_in_range(kGtaoHalf);
}

TEST(OcclusionStress, GtaoAtQuarterResolutionStaysFiniteAndInRange) {
  expect_gtao_finite_and_in_range(kGtaoQuarter);
}

TEST(OcclusionStress, SsaoStaysFiniteAndInRange) {
  for (const Case& c : cases()) {
    const AoRender r = render_occlusion(c.world, kWidth, kHeight, kSsao);
    EXPECT_EQ(r.validation_messages, 0u) << c.name;
    expect_in_range(r.first_ao, c.name);
  }
}

}  // namespace
}  // namespace lg::test
