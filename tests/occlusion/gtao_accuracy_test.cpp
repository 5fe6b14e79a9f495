// GTAO and SSAO on lavapipe against the camera-view ray-traced references, at 160x90 with 128
// rays per pixel: the G-buffer and occlusion are rendered, the full scene is ray traced for the
// same camera, and the G-buffer's depth is traced as a height field, so each test reports the
// method's error (GTAO against the height field) and screen space's (height field against the
// scene) as well as the total. The tolerances are stated beside each case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "nodes/occlusion/reference/height_field_reference.h"
#include "nodes/occlusion/reference/scene_reference.h"
#include "tests/occlusion/ao_render.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr int kRays = 128;
constexpr int kFrames = 8;  // GTAO's temporal accumulation after this many frames

struct Measured {
  AoError first, accumulated, height_field, screen_space;
  double bent_degrees = 0;  // mean angle between GTAO's and the reference's bent normals
};

// Over pixels the reference covers that are occluded enough for a bent normal to mean
// something (k_A < 0.9), and where GTAO wrote one.
double mean_bent_angle(const AoImage& reference, const std::vector<float>& bent) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < reference.visibility.size(); ++i) {
    if (!reference.covered(i) || !(reference.visibility[i] < 0.9f) || bent.size() < 4 * (i + 1)) continue;
    const glm::dvec3 g(bent[4 * i], bent[4 * i + 1], bent[4 * i + 2]), r(reference.bent[i]);
    if (glm::length(g) < 0.5) continue;
    sum += std::acos(std::clamp(glm::dot(glm::normalize(g), glm::normalize(r)), -1.0, 1.0));
    ++n;
  }
  return n ? glm::degrees(sum / n) : 0.0;
}

void print(const char* what, const AoError& e) {
  std::printf("  %-34s MAE %.4f  p95 %.4f  max %.3f  bias %+.4f  (%zu pixels)\n", what, e.mean_absolute, e.p95, e.max,
              e.mean_signed, e.pixels);
}

Measured measure(const World& world, const std::string& node, double radius) {
  const AoRender render = render_occlusion(world, kWidth, kHeight, node, {.frames = kFrames});
  EXPECT_EQ(render.validation_messages, 0u);
  const AoSettings settings{.rays = kRays, .max_distance = radius};
  const RayScene scene(render.view);
  const AoImage reference = trace_scene_reference(render.view, scene, {kWidth, kHeight}, settings);
  const AoImage height_field = trace_height_field_reference(render.view.camera, render.gbuffer, settings);
  Measured m{error_against(reference, render.first_ao), error_against(reference, render.last_ao),
             error_against(height_field, render.last_ao), error_against(reference, height_field),
             mean_bent_angle(reference, render.bent_normals)};
  std::printf("%s\n", node.c_str());
  print("first frame vs scene", m.first);
  print("after 8 frames vs scene", m.accumulated);
  print("after 8 frames vs height field", m.height_field);
  print("height field vs scene", m.screen_space);
  if (!render.bent_normals.empty())
    std::printf("  bent normals: mean angle %.1f degrees to the reference's\n", m.bent_degrees);
  return m;
}

constexpr const char* kGtaoHigh =
    R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "radius": 0.5 } })";
constexpr const char* kGtaoHighHalf =
    R"({ "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high", "radius": 0.5, "resolution_scale": 0.5 } })";
constexpr const char* kSsao = R"({ "id": "ao", "type": "occlusion.ssao", "params": { "samples": 16, "radius": 0.5 } })";

// Measured on lavapipe: GTAO high (2x6) 0.026 after 8 frames and on the first (3x3, the high of
// earlier stops: 0.035), the height field 0.034 from the scene. The issue's target is 0.04 at
// 1280x720 (lumagraph-bench-ao); here 0.045 leaves room for the 128-ray reference's noise (about
// 0.02 per half-occluded pixel, so under 0.001 on the mean) and for rasterization differences
// between drivers. The height field must stay within 0.045 of the scene: it sees the same
// surfaces, less what the bunny hides.
TEST(GtaoAccuracy, BunnyAgainstRayTracing) {
  if (!have_bunny()) GTEST_SKIP() << "../shared/data/mesh/bunny.obj is missing";
  const Measured m = measure(load_example_world("stanford-bunny"), kGtaoHigh, 0.5);
  EXPECT_LE(m.first.mean_absolute, 0.045);
  EXPECT_LE(m.accumulated.mean_absolute, 0.045);
  EXPECT_LE(m.screen_space.mean_absolute, 0.045);
  // Bent normals where k_A < 0.9: measured 9.2 degrees from the reference's on average at 2x6
  // (7.7 at 3x3: two slices sample the azimuth more coarsely than three); 20% above it.
  EXPECT_LE(m.bent_degrees, 11.0);
}

// Half resolution (horizons and denoiser on 80x45, then the joint bilateral upsample) against
// full: issue 19 asks for at most 1.2x the full-resolution error at 1280x720. Measured here, at
// 160x90 where a half-resolution texel covers four times as much of the bunny: 0.0286 after 8
// frames against 0.0259 at full resolution (bent normals 7.9 degrees against 9.2).
TEST(GtaoAccuracy, BunnyAtHalfResolutionAgainstRayTracing) {
  if (!have_bunny()) GTEST_SKIP() << "../shared/data/mesh/bunny.obj is missing";
  const World world = load_example_world("stanford-bunny");
  const Measured full = measure(world, kGtaoHigh, 0.5);
  const Measured half = measure(world, kGtaoHighHalf, 0.5);
  EXPECT_LE(half.accumulated.mean_absolute, 1.2 * full.accumulated.mean_absolute);
  EXPECT_LE(half.bent_degrees, 10.0);
}

// The box's corners are where GTAO errs most: measured 0.055 at 2x6 (0.080 at 3x3) and 0.048
// (height field against the scene); the bounds leave about 20% over 3x3's for drivers and noise.
TEST(GtaoAccuracy, CornellBoxAgainstRayTracing) {
  const Measured m = measure(load_example_world("cornell-box"), kGtaoHigh, 0.5);
  EXPECT_LE(m.accumulated.mean_absolute, 0.10);
  EXPECT_LE(m.screen_space.mean_absolute, 0.06);
  EXPECT_LE(m.bent_degrees, 15.0);  // measured 12.2
}

// The baseline: SSAO with 16 samples measured 0.052; bounded at 0.065 so a regression shows.
TEST(SsaoAccuracy, BunnyAgainstRayTracing) {
  if (!have_bunny()) GTEST_SKIP() << "../shared/data/mesh/bunny.obj is missing";
  const Measured m = measure(load_example_world("stanford-bunny"), kSsao, 0.5);
  EXPECT_LE(m.accumulated.mean_absolute, 0.065);
}

}  // namespace
}  // namespace lg::test
