// Ambient visibility and bent normals against exact and analytic cases: an open plane (1
// exactly), the inside of a closed box (0 exactly), convex objects alone (1 exactly), a wall
// beside a floor and a ceiling with max distance and falloff (analytic, within Monte Carlo
// noise), and bit-identical results over any split of a batch.
#include "nodes/occlusion/estimate/occlusion_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "nodes/raytrace/cosine_sampling.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/occlusion/ray_test_scenes.h"

namespace lg {
namespace {

// A point in [-extent, extent]^3 from a hash (fresh, never zeros).
glm::vec3 random_point(uint64_t seed, uint32_t i, float extent) {
  return {float(hashed_uniform(seed, i, 0) * 2 - 1) * extent, float(hashed_uniform(seed, i, 1) * 2 - 1) * extent,
          float(hashed_uniform(seed, i, 2) * 2 - 1) * extent};
}
glm::vec3 random_direction(uint64_t seed, uint32_t i) {
  return glm::normalize(random_point(seed + 1, i, 1.0f) + glm::vec3(1e-3f, 0.0f, 0.0f));
}

// The Monte Carlo bound used for every statistical check here: stratified sampling has at most
// the variance of independent sampling, so the binomial standard error of the mean over
// `points` estimates of `rays` rays each bounds the noise; checks allow 4 of them (a false
// failure has probability below 1e-4 even for independent samples).
double visibility_tolerance(double expected, int rays, int points) {
  return 4.0 * std::sqrt(std::max(expected * (1.0 - expected), 1e-6) / (double(rays) * points));
}

TEST(OcclusionEstimate, OpenPlaneIsExactlyOne) {
  const RayScene scene(test::scene_of({test::floor_quad(100.0f)}));
  for (uint32_t i = 0; i < 50; ++i) {
    glm::vec3 p = random_point(11, i, 40.0f);
    p.y = 0.0f;
    const OcclusionResult r = estimate_occlusion(scene, p, {0, 1, 0}, {.rays = 256}, i);
    ASSERT_EQ(r.visibility, 1.0f) << "point " << i;
    EXPECT_NEAR(r.bent_normal.y, 1.0f, 0.01f);  // stratified mean of 256 directions
    EXPECT_EQ(r.cone_cos, 0.0f);
  }
}

TEST(OcclusionEstimate, InsideAClosedBoxIsExactlyZero) {
  const RayScene scene(test::scene_of({{make_box({2.0f, 3.0f, 4.0f}), glm::mat4(1.0f)}}));
  for (uint32_t i = 0; i < 50; ++i) {
    const OcclusionResult r =
        estimate_occlusion(scene, random_point(12, i, 0.9f), random_direction(13, i), {.rays = 256}, i);
    ASSERT_EQ(r.visibility, 0.0f) << "point " << i;
    EXPECT_FLOAT_EQ(r.cone_cos, 1.0f);
  }
}

TEST(OcclusionEstimate, ConvexObjectAloneIsExactlyOneOnItsSurface) {
  // Every vertex of a tessellated sphere with its (analytic) normal: the tangent plane supports
  // the polyhedron, whose corners all lie on the sphere. And points on a cube's faces.
  const MeshData sphere = make_sphere(1.5f, 24, 12);
  const RayScene round(test::scene_of({{sphere, glm::translate(glm::mat4(1.0f), {0.3f, -0.2f, 0.1f})}}));
  for (size_t v = 0; v < sphere.positions.size(); v += 7) {
    const glm::vec3 p = sphere.positions[v] + glm::vec3(0.3f, -0.2f, 0.1f);
    ASSERT_EQ(estimate_occlusion(round, p, sphere.normals[v], {.rays = 128}, v).visibility, 1.0f) << "vertex " << v;
  }
  const RayScene cube(test::scene_of({{make_box(glm::vec3(2.0f)), glm::mat4(1.0f)}}));
  for (uint32_t i = 0; i < 30; ++i) {
    glm::vec3 p = random_point(14, i, 0.999f);
    const int axis = int(i % 3);
    const float side = i % 2 ? 1.0f : -1.0f;
    p[axis] = side;
    glm::vec3 n(0.0f);
    n[axis] = side;
    ASSERT_EQ(estimate_occlusion(cube, p, n, {.rays = 128}, i).visibility, 1.0f) << "point " << i;
  }
}

TEST(OcclusionEstimate, WallBesideAFloorMatchesTheAnalyticVisibility) {
  // A point on the floor at distance d from a wall of height h (infinitely long: 2,000 d here):
  // projecting the hemisphere onto the unit disk (cosine weighting = area / pi), the directions
  // toward the wall that pass over it fill half an ellipse of semi-axes 1/sqrt(1 + (h/d)^2) and
  // 1, so k_A = 1/2 + 1 / (2 sqrt(1 + (h/d)^2)); at the foot of a tall wall it tends to 1/2.
  struct Case {
    float distance, height;
  };
  for (const Case c : {Case{1.0f, 1.0f}, Case{1.0f, 3.0f}, Case{2.0f, 0.5f}, Case{0.01f, 100.0f}}) {
    const RayScene scene(test::scene_of(
        {test::floor_quad(4000.0f * c.distance), test::wall_quad(c.distance, c.height, 4000.0f * c.distance)}));
    const double ratio = double(c.height) / c.distance;
    const double expected = 0.5 + 0.5 / std::sqrt(1.0 + ratio * ratio);
    const int rays = 1024, points = 16;
    double mean = 0.0;
    for (int i = 0; i < points; ++i) {
      const glm::vec3 p{0.0f, 0.0f, float(i) * 0.1f * c.distance};  // along the wall
      mean += estimate_occlusion(scene, p, {0, 1, 0}, {.rays = rays}, uint64_t(i)).visibility / points;
    }
    EXPECT_NEAR(mean, expected, visibility_tolerance(expected, rays, points))
        << "d = " << c.distance << ", h = " << c.height;
  }
}

TEST(OcclusionEstimate, BentNormalAtTheFootOfATallWallLeansAway) {
  // Only the half x > 0 is visible: the cosine-weighted mean direction there is (4 / (3 pi), 0,
  // 2/3) with z up (the half-disk's centroid and E[cos] = 2/3), here (x, y) = (4/(3pi), 2/3).
  // Tolerance: a direction component has standard deviation below 0.6, so the mean of 4,096
  // rays is within 4 * 0.6 / 64 = 0.0375 (stratification does far better).
  const RayScene scene(test::scene_of({test::floor_quad(2000.0f), test::wall_quad(0.001f, 1000.0f, 2000.0f)}));
  const OcclusionResult r = estimate_occlusion(scene, {0, 0, 0}, {0, 1, 0}, {.rays = 4096}, 5);
  const glm::vec3 expected = glm::normalize(glm::vec3(4.0f / (3.0f * float(std::numbers::pi)), 2.0f / 3.0f, 0.0f));
  EXPECT_NEAR(r.visibility, 0.5, visibility_tolerance(0.5, 4096, 1));
  EXPECT_NEAR(r.bent_normal.x, expected.x, 0.0375f);
  EXPECT_NEAR(r.bent_normal.y, expected.y, 0.0375f);
  EXPECT_NEAR(r.bent_normal.z, 0.0f, 0.0375f);
  // GTAO's cone: the cosine-weighted fraction of a cone of half-angle a is sin^2 a = k_A.
  EXPECT_NEAR(std::sin(r.cone_angle) * std::sin(r.cone_angle), r.visibility, 1e-6);
  EXPECT_NEAR(r.cone_cos, std::cos(r.cone_angle), 1e-6);
}

TEST(OcclusionEstimate, MaxDistanceAndObscuranceUnderACeiling) {
  // A ceiling at height H over the point; with max distance D and a = H / D < 1 a ray at mu =
  // cos(theta) hits at H / mu. With p(mu) = 2 mu: falloff none counts only the rays reaching
  // past D, mu < a, so k_A = a^2; the obscurance curve rho(x) = x (2 - x) at x = a / mu gives
  // k_A = a^2 + int_a^1 (2a/mu - a^2/mu^2) 2 mu dmu = 4a - 3a^2 + 2a^2 ln a.
  const float height = 1.0f, max_distance = 2.5f;
  const RayScene scene(test::scene_of({{make_quad(1e4f, 1e4f), glm::translate(glm::mat4(1.0f), {0, height, 0})}}));
  const double a = height / max_distance;
  const int rays = 1024, points = 16;
  double none = 0.0, obscurance = 0.0;
  for (int i = 0; i < points; ++i) {
    const glm::vec3 p{float(i) * 0.37f, 0.0f, float(i) * -0.21f};
    none += estimate_occlusion(scene, p, {0, 1, 0}, {.rays = rays, .max_distance = max_distance}, i).visibility;
    obscurance +=
        estimate_occlusion(scene, p, {0, 1, 0},
                           {.rays = rays, .max_distance = max_distance, .falloff = OcclusionFalloff::obscurance}, i)
            .visibility;
  }
  const double expected_none = a * a, expected_obscurance = 4 * a - 3 * a * a + 2 * a * a * std::log(a);
  EXPECT_NEAR(none / points, expected_none, visibility_tolerance(expected_none, rays, points));
  // rho lies in [0, 1], so its variance is at most that of a binomial with the same mean.
  EXPECT_NEAR(obscurance / points, expected_obscurance, visibility_tolerance(expected_obscurance, rays, points));
  // Infinite rays: the ceiling covers the whole hemisphere.
  EXPECT_EQ(estimate_occlusion(scene, {0, 0, 0}, {0, 1, 0}, {.rays = rays}, 1).visibility, 0.0f);
}

TEST(OcclusionEstimate, AnySplitOfABatchIsBitIdentical) {
  const RayScene scene(test::scene_of({test::floor_quad(20.0f),
                                       test::wall_quad(1.0f, 2.0f, 20.0f),
                                       {make_sphere(0.7f), glm::translate(glm::mat4(1.0f), {1.0f, 0.7f, 0.5f})}}));
  std::vector<SurfacePoint> points(301);
  for (uint32_t i = 0; i < points.size(); ++i) {
    points[i].position = random_point(21, i, 3.0f);
    points[i].position.y = 0.0f;
    points[i].normal = {0, 1, 0};
  }
  const OcclusionSettings settings{.rays = 64};
  const std::vector<OcclusionResult> whole = estimate_occlusion_many(scene, points, settings, 42);
  std::vector<OcclusionResult> parts;
  size_t reported = 0;
  for (size_t begin : {size_t(0), size_t(100), size_t(257)}) {
    const size_t end = begin == 0 ? 100 : begin == 100 ? 257 : points.size();
    auto part = estimate_occlusion_many(scene, std::span(points).subspan(begin, end - begin), settings, 42, begin,
                                        [&](size_t done) { reported = done; });
    EXPECT_EQ(reported, end - begin);
    parts.insert(parts.end(), part.begin(), part.end());
  }
  ASSERT_EQ(parts.size(), whole.size());
  bool some_occluded = false;
  for (size_t i = 0; i < whole.size(); ++i) {
    ASSERT_EQ(std::memcmp(&parts[i], &whole[i], sizeof(OcclusionResult)), 0) << "point " << i;
    some_occluded |= whole[i].visibility < 1.0f;
  }
  EXPECT_TRUE(some_occluded);  // the comparison covers real occlusion, not only open floor
}

TEST(OcclusionEstimate, SphereVisibilityInTheOpenOverAFloorAndInsideABox) {
  const RayScene empty(std::vector<glm::vec3>{}, std::vector<uint32_t>{});
  const SphereVisibility open = estimate_sphere_visibility(empty, {1, 2, 3}, {.rays = 64}, 1);
  EXPECT_EQ(open.visibility, 1.0f);
  EXPECT_TRUE(std::isinf(open.nearest_hit));
  // Above an (effectively infinite) floor the lower half of the sphere is blocked: 1/2 up to
  // noise (binomial bound, 4 standard errors), and the bent normal points up.
  const RayScene floor(test::scene_of({test::floor_quad(1e5f)}));
  const SphereVisibility above = estimate_sphere_visibility(floor, {0, 0.5f, 0}, {.rays = 4096}, 2);
  EXPECT_NEAR(above.visibility, 0.5, visibility_tolerance(0.5, 4096, 1));
  EXPECT_GT(above.bent_normal.y, 0.99f);
  EXPECT_EQ(above.backface_fraction, 0.0f);
  // The unnormalised mean unoccluded direction: the mean of z over the upper half, 1/2, times
  // its share, 1/2. A ray's V z has a standard deviation of 0.32, so 4096 rays give 0.005; 0.02
  // is 4 of those. The nearest hit is the floor below, 0.5 away, within the few degrees the
  // rays nearest straight down miss it by.
  EXPECT_NEAR(above.mean_direction.y, 0.25, 0.02);
  EXPECT_NEAR(above.mean_direction.x, 0.0, 0.02);
  EXPECT_NEAR(above.mean_direction.z, 0.0, 0.02);
  EXPECT_GE(above.nearest_hit, 0.5f * (1.0f - 1e-5f));
  EXPECT_LE(above.nearest_hit, 0.51f);
  const RayScene box(test::scene_of({{make_box(glm::vec3(1.0f)), glm::mat4(1.0f)}}));
  const SphereVisibility inside = estimate_sphere_visibility(box, {0.1f, -0.2f, 0.3f}, {.rays = 256}, 3);
  EXPECT_EQ(inside.visibility, 0.0f);
  EXPECT_EQ(inside.backface_fraction, 1.0f);
}

TEST(OcclusionEstimate, SettingsOutOfRangeAreRejected) {
  EXPECT_THROW(check_occlusion_settings({.rays = 0}), std::invalid_argument);
  EXPECT_THROW(check_occlusion_settings({.rays = max_rays_per_point + 1}), std::invalid_argument);
  EXPECT_THROW(check_occlusion_settings({.max_distance = 0.0f}), std::invalid_argument);
  EXPECT_THROW(check_occlusion_settings({.max_distance = std::nanf("")}), std::invalid_argument);
  EXPECT_THROW(check_occlusion_settings({.falloff = OcclusionFalloff::obscurance}), std::invalid_argument);
  EXPECT_NO_THROW(check_occlusion_settings({.rays = max_rays_per_point}));
}

}  // namespace
}  // namespace lg
