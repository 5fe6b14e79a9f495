// The representative points (Karis 2013) on random configurations: each lies on the light,
// it is the light's point closest to the reflection ray (checked against a brute-force search
// over the light), the direction is the reflection itself where the ray hits the light, and
// the normalisation matches its stated form. Geometry tolerances are float rounding (1e-4
// relative to the light's distance) plus the search's grid spacing.
#include "nodes/lighting/deferred/area_light_specular.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "tests/lighting/area_light_cases.h"

namespace lg {
namespace {

using glm::dvec3;

// Distance from point x to the line through the origin along unit r.
double line_distance(dvec3 x, dvec3 r) {
  return glm::length(x - glm::dot(x, r) * r);
}

dvec3 point_of(const RepresentativePoint& rp) {
  return glm::dvec3(rp.direction) * double(rp.distance);
}

TEST(AreaLightSpecular, SpherePointIsClosestToRay) {
  CaseGenerator g(401);
  for (int i = 0; i < 2000; ++i) {
    SphereLightD light = g.sphere();
    Shading s = g.shading(light.center, light.radius, 1.0, Horizon::kAbove);
    dvec3 r = g.direction();
    float alpha = float(g.uniform(0.01, 1.0));
    RepresentativePoint rp = sphere_specular_point(to_float(light), to_float(s.p), to_float(r), alpha);
    dvec3 c = light.center - s.p;
    double tol = 1e-4 * glm::length(c);
    dvec3 x = point_of(rp);
    double gap = line_distance(c, r);
    if (gap <= light.radius) {
      // The ray passes through the sphere: the point is on the ray itself.
      EXPECT_LE(line_distance(x, r), tol) << i;
    } else {
      EXPECT_NEAR(glm::length(x - c), light.radius, tol) << i;
      EXPECT_NEAR(line_distance(x, r), gap - light.radius, tol) << i;
    }
    double widened = std::min(1.0, alpha + light.radius / (2.0 * glm::length(c)));
    EXPECT_NEAR(rp.normalization, std::pow(alpha / widened, 2.0), 1e-5) << i;
  }
}

TEST(AreaLightSpecular, TubePointIsClosestToRay) {
  CaseGenerator g(402);
  for (int i = 0; i < 1000; ++i) {
    TubeLightD light = g.tube();
    Shading s = g.shading(light_center(light), bounding_radius(light), 1.0, Horizon::kAbove);
    dvec3 r = g.direction();
    RepresentativePoint rp = tube_specular_point(to_float(light), to_float(s.p), to_float(r), 0.3f);
    dvec3 a = light.end0 - s.p;
    dvec3 d = light.end1 - light.end0;
    double tol = 1e-4 * glm::length(light_center(light) - s.p);
    // Brute force: the segment point closest to the reflection line.
    double best = 1e300;
    for (int k = 0; k <= 4000; ++k) best = std::min(best, line_distance(a + (k / 4000.0) * d, r));
    double grid = glm::length(d) / 4000.0;
    dvec3 x = point_of(rp);
    // On the capsule (within the radius of the segment) ...
    double to_segment = 1e300;
    for (int k = 0; k <= 4000; ++k) to_segment = std::min(to_segment, glm::length(x - (a + (k / 4000.0) * d)));
    EXPECT_LE(to_segment, light.radius + tol + grid) << i;
    // ... and as close to the ray as the capsule gets.
    EXPECT_NEAR(line_distance(x, r), std::max(best - light.radius, 0.0), tol + grid) << i;
  }
}

TEST(AreaLightSpecular, RectPointIsOnLightAndHitsWhereRayDoes) {
  CaseGenerator g(403);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    RectLightD light = g.rect();
    light.two_sided = true;
    Shading s = g.shading(light.center, bounding_radius(light), 1.0, Horizon::kAbove, dvec3(0.0), 1.5, 5.0);
    dvec3 c = light.center - s.p;
    // Half the rays aim at a random point of the rectangle.
    dvec3 r = i % 2 ? g.direction()
                    : glm::normalize(c + g.uniform(-0.95, 0.95) * light.half_x + g.uniform(-0.95, 0.95) * light.half_y);
    RepresentativePoint rp = rect_specular_point(to_float(light), to_float(s.p), to_float(r), 0.3f);
    double tol = 1e-4 * glm::length(c);
    dvec3 local = point_of(rp) - c;
    dvec3 nl = glm::normalize(glm::cross(light.half_x, light.half_y));
    EXPECT_NEAR(glm::dot(local, nl), 0.0, tol) << i;
    EXPECT_LE(std::fabs(glm::dot(local, light.half_x)) / glm::dot(light.half_x, light.half_x), 1.0 + 1e-4) << i;
    EXPECT_LE(std::fabs(glm::dot(local, light.half_y)) / glm::dot(light.half_y, light.half_y), 1.0 + 1e-4) << i;
    if (i % 2 == 0) {
      ++hits;
      EXPECT_GE(glm::dot(glm::dvec3(rp.direction), r), 1.0 - 1e-6) << i;
    }
  }
  EXPECT_EQ(hits, 1000);
}

TEST(AreaLightSpecular, PointLightLimitIsUnnormalised) {
  SphereLight tiny{glm::vec3(0.0f, 3.0f, 0.0f), 1e-6f, 1.0f};
  RepresentativePoint rp = sphere_specular_point(tiny, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 0.5f);
  EXPECT_NEAR(rp.normalization, 1.0f, 1e-5f);
  EXPECT_NEAR(rp.direction.y, 1.0f, 1e-6f);
  // A mirror gets a finite, small normalisation (the clamped alpha over the widened one).
  RepresentativePoint mirror = sphere_specular_point(SphereLight{glm::vec3(0.0f, 3.0f, 0.0f), 0.5f, 1.0f},
                                                     glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 0.0f);
  EXPECT_GT(mirror.normalization, 0.0f);
  EXPECT_LT(mirror.normalization, 1e-5f);
}

}  // namespace
}  // namespace lg
