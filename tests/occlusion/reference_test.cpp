// The camera-view AO references on cases with exact answers: an open plane is unoccluded
// (k_A = 1) for the full-scene and the height-field reference alike, the inside of a closed box
// is fully occluded (k_A = 0) with infinite rays, the falloff ramp is GTAO's, a pixel gets the
// same directions from both references, and bad input names what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/common/gbuffer_normal.h"
#include "nodes/occlusion/reference/height_field_reference.h"
#include "nodes/occlusion/reference/scene_reference.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/ray_scene.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/occlusion_worlds.h"

namespace lg::test {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 36;

AoImage scene_reference(const World& world, const AoSettings& settings, bool cull_backfaces = true) {
  const SceneView view = make_scene_view(world, float(kWidth) / kHeight);
  const RayScene scene(view);
  return trace_scene_reference(view, scene, {kWidth, kHeight, cull_backfaces}, settings);
}

World open_plane() {
  return WorldBuilder().add(make_quad(40.0f, 40.0f), {}).camera({0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, -3.0f}).world();
}

// Rays above a plane never meet it again: exactly 1, with or without a maximum distance.
TEST(AoReference, OpenPlaneIsUnoccluded) {
  for (double max_distance : {double(INFINITY), 0.5}) {
    const AoImage ao = scene_reference(open_plane(), {.rays = 64, .max_distance = max_distance});
    ASSERT_GT(ao.covered_count(), kWidth * kHeight / 3) << "the camera sees the plane";
    for (size_t i = 0; i < ao.visibility.size(); ++i) {
      if (!ao.covered(i)) continue;
      ASSERT_EQ(ao.visibility[i], 1.0f) << "pixel " << i << ", max distance " << max_distance;
    }
  }
}

// From inside a closed box every ray meets a wall: exactly 0 with infinite rays. The camera
// sees the walls' back faces, so they are drawn two-sided (cull_backfaces off).
TEST(AoReference, InsideClosedBoxIsOccluded) {
  const World world =
      WorldBuilder().add(make_box({4.0f, 3.0f, 4.0f}), {}).camera({0.3f, 0.2f, 0.1f}, {1.0f, -0.5f, -1.0f}).world();
  const AoImage ao = scene_reference(world, {.rays = 64}, false);
  ASSERT_EQ(ao.covered_count(), size_t(kWidth) * kHeight) << "every pixel sees a wall";
  for (size_t i = 0; i < ao.visibility.size(); ++i) ASSERT_EQ(ao.visibility[i], 0.0f) << "pixel " << i;
  // Culling the back faces (scene.gbuffer's default) leaves nothing to see from inside.
  EXPECT_EQ(scene_reference(world, {.rays = 4}, true).covered_count(), 0u);
}

// GTAO's ramp: full occlusion up to 62% of the radius, none from the radius on, linear between.
TEST(AoReference, FalloffIsGtaoRamp) {
  const AoSettings s{.max_distance = 2.0};
  EXPECT_EQ(occlusion_weight(0.0, s), 1.0);
  EXPECT_EQ(occlusion_weight(1.24, s), 1.0);
  EXPECT_NEAR(occlusion_weight(1.62, s), 0.5, 1e-12);
  EXPECT_EQ(occlusion_weight(2.0, s), 0.0);
  EXPECT_EQ(occlusion_weight(INFINITY, s), 0.0);
  EXPECT_EQ(occlusion_weight(1e9, AoSettings{}), 1.0) << "infinite rays: every hit occludes";
}

// The directions are cosine-distributed: their mean cosine is 2/3 within the stratified
// estimate's error (far below 1e-3 at 4096 rays), and a pixel's set does not depend on who asks.
TEST(AoReference, DirectionsAreCosineWeightedAndRepeatable) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  const std::vector<glm::dvec3> d = cosine_directions(n, {.rays = 4096, .seed = 9}, 1234);
  double mean_cos = 0;
  for (const glm::dvec3& v : d) {
    ASSERT_GE(glm::dot(v, n), 0.0);
    mean_cos += glm::dot(v, n) / double(d.size());
  }
  EXPECT_NEAR(mean_cos, 2.0 / 3.0, 1e-3);
  EXPECT_EQ(cosine_directions(n, {.rays = 16}, 7), cosine_directions(n, {.rays = 16}, 7));
  EXPECT_NE(cosine_directions(n, {.rays = 16}, 7), cosine_directions(n, {.rays = 16}, 8));
}

// A G-buffer of the plane y = 0 written on the CPU (device depth = near / distance along -z):
// the height field of a plane is the plane, so every pixel gets exactly 1 there too.
TEST(AoReference, HeightFieldOfAnOpenPlaneIsUnoccluded) {
  const SceneView view = make_scene_view(open_plane(), float(kWidth) / kHeight);
  const CameraPixels pixels(view.camera, kWidth, kHeight);
  GbufferReadback g{kWidth, kHeight, std::vector<float>(kWidth * kHeight, 0.0f),
                    std::vector<float>(4 * kWidth * kHeight, 0.5f)};
  size_t on_plane = 0;
  for (uint32_t y = 0; y < kHeight; ++y)
    for (uint32_t x = 0; x < kWidth; ++x) {
      const glm::dvec3 d = pixels.ray_direction(x, y);
      if (!(d.y < -1e-3)) continue;  // above the horizon: far plane (depth 0)
      const glm::dvec3 p = pixels.eye() + d * (-pixels.eye().y / d.y);
      const glm::dvec3 v = glm::dvec3(pixels.view_from_world() * glm::dvec4(p, 1.0));
      const size_t i = size_t(y) * kWidth + x;
      g.depth[i] = float(pixels.near_plane() / -v.z);
      const glm::dvec3 up = encode_gbuffer_normal({0.0, 1.0, 0.0});
      for (int c = 0; c < 3; ++c) g.normal[4 * i + c] = float(up[c]);
      ++on_plane;
    }
  for (double max_distance : {double(INFINITY), 0.5}) {
    const AoImage ao = trace_height_field_reference(view.camera, g, {.rays = 64, .max_distance = max_distance});
    EXPECT_EQ(ao.covered_count(), on_plane);
    for (size_t i = 0; i < ao.visibility.size(); ++i) {
      if (!ao.covered(i)) continue;
      ASSERT_EQ(ao.visibility[i], 1.0f) << "pixel " << i << ", max distance " << max_distance;
    }
  }
}

TEST(AoReference, MismatchedGbufferIsAnError) {
  const SceneView view = make_scene_view(open_plane(), 1.0f);
  const GbufferReadback g{4, 4, std::vector<float>(15), std::vector<float>(64)};
  try {
    trace_height_field_reference(view.camera, g, {});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("4x4 G-buffer needs 16 depths"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lg::test
