// Degenerate input to the real-time area-light formulas: zero sizes, the shaded point on or
// inside the light, normals facing away, grazing angles, huge distances and values, NaN and
// Inf. Every output must be finite; irradiance must lie in [0, pi L] (no uniformly emitting
// light gives more), specular normalisations in [0, 1] and directions unit or zero.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "nodes/lighting/deferred/area_light_formulas.h"
#include "nodes/lighting/deferred/area_light_specular.h"
#include "tests/lighting/area_light_cases.h"

namespace lg {
namespace {

using glm::vec3;

constexpr float kPi = 3.14159265f;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// pi L, with float rounding: the formulas reach pi L exactly only when the light fills the
// hemisphere, and round within a few ulps of it.
void expect_irradiance(float e, float radiance, const char* what) {
  ASSERT_TRUE(std::isfinite(e)) << what;
  EXPECT_GE(e, 0.0f) << what;
  if (std::isfinite(radiance) && radiance >= 0.0f) {
    EXPECT_LE(e, kPi * radiance * (1.0f + 1e-5f)) << what;
  }
}

void expect_point(const RepresentativePoint& r, const char* what) {
  ASSERT_TRUE(std::isfinite(r.normalization) && std::isfinite(r.distance)) << what;
  EXPECT_GE(r.normalization, 0.0f) << what;
  EXPECT_LE(r.normalization, 1.0f) << what;
  float len = glm::length(r.direction);
  ASSERT_TRUE(std::isfinite(len)) << what;
  EXPECT_TRUE(len == 0.0f || std::fabs(len - 1.0f) < 1e-5f) << what << ": |direction| " << len;
}

void check_all(const SphereLight& sphere, const TubeLight& tube, const RectLight& rect, vec3 p, vec3 n, vec3 reflection,
               float alpha) {
  expect_irradiance(sphere_irradiance(sphere, p, n), sphere.radiance, "sphere");
  expect_irradiance(tube_irradiance(tube, p, n), tube.radiance, "tube");
  expect_irradiance(rect_irradiance(rect, p, n), rect.radiance, "rect");
  expect_point(sphere_specular_point(sphere, p, reflection, alpha), "sphere specular");
  expect_point(tube_specular_point(tube, p, reflection, alpha), "tube specular");
  expect_point(rect_specular_point(rect, p, reflection, alpha), "rect specular");
}

const SphereLight kSphere{vec3(1.0f, 2.0f, 3.0f), 0.5f, 10.0f};
const TubeLight kTube{vec3(1.0f, 2.0f, 3.0f), vec3(2.0f, 2.5f, 3.0f), 0.25f, 10.0f};
const RectLight kRect{vec3(1.0f, 2.0f, 3.0f), vec3(0.5f, 0.0f, 0.0f), vec3(0.0f, 0.0f, 0.25f), 10.0f, false};
const vec3 kP(1.2f, -1.0f, 3.1f);
const vec3 kN = glm::normalize(vec3(0.1f, 1.0f, 0.05f));
const vec3 kR = glm::normalize(vec3(0.2f, 1.0f, -0.1f));

TEST(AreaLightStress, ZeroSizeLightsGiveNothing) {
  SphereLight sphere = kSphere;
  sphere.radius = 0.0f;
  TubeLight tube = kTube;
  tube.radius = 0.0f;
  RectLight rect = kRect;
  rect.half_x = vec3(0.0f);
  EXPECT_EQ(sphere_irradiance(sphere, kP, kN), 0.0f);
  EXPECT_EQ(tube_irradiance(tube, kP, kN), 0.0f);
  EXPECT_EQ(rect_irradiance(rect, kP, kN), 0.0f);
  check_all(sphere, tube, rect, kP, kN, kR, 0.3f);
  rect.two_sided = true;
  EXPECT_EQ(rect_irradiance(rect, kP, kN), 0.0f);
}

TEST(AreaLightStress, ZeroLengthTubeIsSphere) {
  TubeLight tube{kSphere.center, kSphere.center, kSphere.radius, kSphere.radiance};
  EXPECT_FLOAT_EQ(tube_irradiance(tube, kP, kN), sphere_irradiance(kSphere, kP, kN));
}

TEST(AreaLightStress, FacingAwayGivesZero) {
  vec3 away = glm::normalize(kP - kSphere.center);
  EXPECT_EQ(sphere_irradiance(kSphere, kP, away), 0.0f);
  EXPECT_EQ(tube_irradiance(kTube, kP, away), 0.0f);
  EXPECT_EQ(rect_irradiance(kRect, kP, away), 0.0f);
  // kRect emits toward -y: from above it nothing is seen, even facing it.
  vec3 behind = kRect.center + vec3(0.0f, 1.0f, 0.0f);
  EXPECT_EQ(rect_irradiance(kRect, behind, vec3(0.0f, -1.0f, 0.0f)), 0.0f);
  EXPECT_EQ(rect_specular_point(kRect, behind, vec3(0.0f, -1.0f, 0.0f), 0.5f).normalization, 0.0f);
}

// On the surface, inside, and at the center of each light, with normals all around.
TEST(AreaLightStress, PointOnOrInsideTheLight) {
  CaseGenerator g(301);
  std::vector<vec3> points{
      kSphere.center, kSphere.center + vec3(0.5f, 0.0f, 0.0f),    kTube.end0,
      kTube.end1,     0.5f * (kTube.end0 + kTube.end1),           kTube.end0 + vec3(0.0f, 0.0f, 0.25f),
      kRect.center,   kRect.center + kRect.half_x + kRect.half_y, kRect.center + 0.5f * kRect.half_x};
  for (vec3 p : points) {
    for (int i = 0; i < 50; ++i)
      check_all(kSphere, kTube, kRect, p, to_float(g.direction()), to_float(g.direction()), 0.2f);
  }
}

TEST(AreaLightStress, GrazingAndHugeDistances) {
  CaseGenerator g(302);
  for (float dist : {1e-3f, 1.0f, 1e3f, 1e6f, 1e12f, 1e18f, 1e30f}) {
    for (int i = 0; i < 50; ++i) {
      vec3 dir = to_float(g.direction());
      vec3 p = kSphere.center + dist * dir;
      // n perpendicular to the direction of the light: the horizon through its center.
      vec3 grazing = glm::normalize(glm::cross(dir, to_float(g.direction())));
      check_all(kSphere, kTube, kRect, p, grazing, to_float(g.direction()), 0.5f);
      check_all(kSphere, kTube, kRect, p, -dir, to_float(g.direction()), 0.0f);
    }
  }
}

TEST(AreaLightStress, HugeAndTinyValues) {
  for (float size : {1e-38f, 1e-20f, 1e20f, 1e30f}) {
    for (float radiance : {0.0f, 1e-30f, 1e30f}) {
      SphereLight sphere{kSphere.center, size, radiance};
      TubeLight tube{kTube.end0, kTube.end1, size, radiance};
      RectLight rect{kRect.center, size * vec3(1.0f, 0.0f, 0.0f), size * vec3(0.0f, 0.0f, 1.0f), radiance, true};
      check_all(sphere, tube, rect, kP, kN, kR, 1.0f);
    }
  }
}

// Any NaN or Inf, in any input, gives a finite result.
TEST(AreaLightStress, NonFiniteInputs) {
  for (float bad : {kNaN, kInf, -kInf}) {
    for (int field = 0; field < 8; ++field) {
      SphereLight sphere = kSphere;
      TubeLight tube = kTube;
      RectLight rect = kRect;
      vec3 p = kP;
      vec3 n = kN;
      vec3 r = kR;
      float alpha = 0.3f;
      switch (field) {
        case 0:
          p.y = bad;
          break;
        case 1:
          n.x = bad;
          break;
        case 2:
          sphere.center.z = bad, tube.end0.z = bad, rect.center.z = bad;
          break;
        case 3:
          sphere.radius = bad, tube.radius = bad, rect.half_x.x = bad;
          break;
        case 4:
          sphere.radiance = bad, tube.radiance = bad, rect.radiance = bad;
          break;
        case 5:
          tube.end1.x = bad, rect.half_y.z = bad;
          break;
        case 6:
          r.y = bad;
          break;
        case 7:
          alpha = bad;
          break;
      }
      check_all(sphere, tube, rect, p, n, r, alpha);
    }
  }
  EXPECT_EQ(sphere_irradiance(kSphere, kP, vec3(0.0f)), 0.0f);
  EXPECT_EQ(tube_irradiance(kTube, kP, vec3(0.0f)), 0.0f);
  EXPECT_EQ(rect_irradiance(kRect, kP, vec3(0.0f)), 0.0f);
}

// Random lights and points anywhere, any normal; half the points within 10% of the sphere
// light's surface, inside or out: bounded and finite.
TEST(AreaLightStress, RandomAnywhere) {
  CaseGenerator g(303);
  for (int i = 0; i < 20000; ++i) {
    SphereLightD sphere = g.sphere();
    glm::dvec3 p = i % 2 ? sphere.center + sphere.radius * g.uniform(0.9, 1.1) * g.direction()
                         : glm::dvec3(g.uniform(-12, 12), g.uniform(-12, 12), g.uniform(-12, 12));
    check_all(to_float(sphere), to_float(g.tube()), to_float(g.rect()), to_float(p), to_float(g.direction()),
              to_float(g.direction()), float(g.uniform(0.0, 1.0)));
  }
}

}  // namespace
}  // namespace lg
