// RayScene: closest hits with distance, normal and primitive, occlusion within t_max, world
// transforms of draws, empty and degenerate geometry, and errors for bad input.
#include "nodes/raytrace/ray_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

constexpr float inf = std::numeric_limits<float>::infinity();

TEST(RayScene, ClosestHitHasDistanceNormalAndPrimitive) {
  // Two parallel floors: y = 0 (draw 0) and y = 2 (draw 1, each quad is 2 triangles).
  const RayScene scene(
      test::scene_of({test::floor_quad(10.0f), {make_quad(10.0f, 10.0f), glm::translate(glm::mat4(1.0f), {0, 2, 0})}}));
  ASSERT_EQ(scene.triangle_count(), 4u);
  const auto down = scene.intersect({0.3f, 1.0f, 0.2f}, {0, -1, 0}, inf);
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->distance, 1.0f, 1e-6f);
  EXPECT_NEAR(down->normal.y, 1.0f, 1e-6f);
  EXPECT_LT(down->primitive, 2u);
  const auto up = scene.intersect({0.3f, 1.0f, 0.2f}, {0, 1, 0}, inf);
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->distance, 1.0f, 1e-6f);
  EXPECT_NEAR(up->normal.y, 1.0f, 1e-6f);  // the upper floor faces +Y too: we hit its back
  EXPECT_GE(up->primitive, 2u);
  EXPECT_FALSE(scene.intersect({20.0f, 1.0f, 0.0f}, {0, -1, 0}, inf));
}

TEST(RayScene, OcclusionRespectsTMax) {
  const RayScene scene(test::scene_of({test::floor_quad(10.0f)}));
  EXPECT_TRUE(scene.occluded({0, 1, 0}, {0, -1, 0}, inf));
  EXPECT_TRUE(scene.occluded({0, 1, 0}, {0, -1, 0}, 1.01f));
  EXPECT_FALSE(scene.occluded({0, 1, 0}, {0, -1, 0}, 0.99f));
  EXPECT_FALSE(scene.intersect({0, 1, 0}, {0, -1, 0}, 0.99f));
  EXPECT_FALSE(scene.occluded({0, 1, 0}, {0, 1, 0}, inf));
}

TEST(RayScene, PacketsAgreeWithSingleRays) {
  // A floor and a wall: from a point near their crease, rays in every direction, some blocked,
  // in full and partial packets, with and without a t_max that cuts some hits off.
  const RayScene scene(test::scene_of({test::floor_quad(10.0f), test::wall_quad(0.5f, 1.0f, 10.0f)}));
  const glm::vec3 origin{0.0f, 0.2f, 0.1f};
  std::vector<glm::vec3> directions;
  for (int i = 0; i < 29; ++i) {
    const float a = 0.7f * float(i), b = 0.37f * float(i) - 5.0f;
    directions.push_back(glm::normalize(glm::vec3(std::cos(a), std::sin(b), std::sin(a))));
  }
  for (float t_max : {inf, 0.6f}) {
    size_t blocked_count = 0;
    for (size_t first = 0; first < directions.size(); first += RayScene::packet_size) {
      const size_t n = std::min(RayScene::packet_size, directions.size() - first);
      bool blocked[RayScene::packet_size];
      std::optional<RayHit> hits[RayScene::packet_size];
      scene.occluded_packet(origin, std::span(directions).subspan(first, n), t_max, std::span(blocked, n));
      scene.intersect_packet(origin, std::span(directions).subspan(first, n), t_max, std::span(hits, n));
      for (size_t j = 0; j < n; ++j) {
        EXPECT_EQ(blocked[j], scene.occluded(origin, directions[first + j], t_max)) << "ray " << first + j;
        const std::optional<RayHit> single = scene.intersect(origin, directions[first + j], t_max);
        ASSERT_EQ(hits[j].has_value(), single.has_value()) << "ray " << first + j;
        if (single) {
          EXPECT_EQ(hits[j]->primitive, single->primitive);
          EXPECT_NEAR(hits[j]->distance, single->distance, 1e-6f * single->distance);
          EXPECT_EQ(hits[j]->normal, single->normal);
        }
        blocked_count += blocked[j];
      }
    }
    EXPECT_GT(blocked_count, 0u);
    EXPECT_LT(blocked_count, directions.size());
  }
}

TEST(RayScene, RawTrianglesAndBounds) {
  const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<uint32_t> indices{0, 1, 2};
  const RayScene scene(positions, indices);
  EXPECT_EQ(scene.bounds_min(), glm::vec3(0.0f));
  EXPECT_EQ(scene.bounds_max(), glm::vec3(1, 1, 0));
  const auto hit = scene.intersect({0.2f, 0.2f, 1.0f}, {0, 0, -1}, inf);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->normal.z, 1.0f, 1e-6f);  // counter-clockwise seen from +Z
}

TEST(RayScene, EmptyAndDegenerateGeometryIsNeverHit) {
  const RayScene empty(std::vector<glm::vec3>{}, std::vector<uint32_t>{});
  EXPECT_TRUE(empty.empty());
  EXPECT_FALSE(empty.occluded({0, 0, 0}, {0, 0, 1}, inf));
  EXPECT_FALSE(empty.intersect({0, 0, 0}, {0, 0, 1}, inf));
  // A zero-area triangle (three equal corners) and a sliver (collinear corners) on the ray.
  const std::vector<glm::vec3> positions{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {-1, 0, 2}, {0, 0, 2}, {1, 0, 2}};
  const std::vector<uint32_t> indices{0, 1, 2, 3, 4, 5};
  const RayScene degenerate(positions, indices);
  EXPECT_FALSE(degenerate.occluded({0, 0, 0}, {0, 0, 1}, inf));
}

TEST(RayScene, BadInputNamesTheProblem) {
  const std::vector<glm::vec3> nan_positions{{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
  const std::vector<uint32_t> indices{0, 1, 2};
  try {
    RayScene scene(nan_positions, indices, "bunny.obj");
    FAIL() << "a NaN vertex was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bunny.obj: vertex 2 has a non-finite position"), std::string::npos)
        << e.what();
  }
  const std::vector<uint32_t> out_of_range{0, 1, 3};
  EXPECT_THROW(RayScene(nan_positions, out_of_range), std::invalid_argument);
  const std::vector<uint32_t> not_triangles{0, 1};
  EXPECT_THROW(RayScene(nan_positions, not_triangles), std::invalid_argument);

  SceneView view = test::scene_of({test::floor_quad(1.0f)});
  view.draws[0].world[3][0] = std::numeric_limits<float>::infinity();
  try {
    RayScene scene(view);
    FAIL() << "an infinite transform was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has a non-finite world position"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lg
