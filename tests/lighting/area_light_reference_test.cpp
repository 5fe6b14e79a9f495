// The reference quadrature against closed forms: a sphere (Snyder's form factor, above and
// across the horizon), a rectangle (the Lambert polygon formula on the horizon-clipped
// polygon) and a zero-length capsule (a sphere). All to 1e-9 relative, with rel_tol 1e-11.
#include "nodes/lighting/deferred/area_light_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <vector>

#include "tests/lighting/area_light_cases.h"

namespace lg {
namespace {

using glm::dvec3;

constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-11;  // asked of the quadrature
// Checked against the closed forms: 100 times the target, room for the closed forms' own
// rounding; an absolute floor of 1e-12 of the bounding sphere's irradiance for cases the horizon
// leaves almost dark (the quadrature's own floor is 1e-14 of it).
constexpr double kCheck = 1e-9;
constexpr double kFloor = 1e-12;

// Snyder's sphere form factor in double, derived independently of the float formula.
double sphere_exact(double cos_w, double sin2_a) {
  if (cos_w * cos_w >= sin2_a) return cos_w > 0.0 ? kPi * sin2_a * cos_w : 0.0;
  double sin_a = std::sqrt(sin2_a);
  double cos_a = std::sqrt(1.0 - sin2_a);
  double sin_w = std::sqrt(1.0 - cos_w * cos_w);
  double y = -cos_a * cos_w / (sin_a * sin_w);
  double q = sin_w * std::sqrt(1.0 - y * y);
  return cos_w * std::acos(y) * sin2_a - cos_a * sin_a * q + std::atan2(q * sin_a, cos_a);
}

double sphere_exact(const SphereLightD& light, dvec3 p, dvec3 n) {
  dvec3 d = light.center - p;
  double dist = glm::length(d);
  return light.radiance * sphere_exact(glm::dot(n, d) / dist, light.radius * light.radius / (dist * dist));
}

// The Lambert polygon formula: E = L/2 |sum over edges of theta n.normalize(a x b)| on the
// rectangle clipped to the horizon of n (Sutherland-Hodgman).
double rect_exact(const RectLightD& light, dvec3 p, dvec3 n) {
  dvec3 c = light.center - p;
  dvec3 hx = light.half_x;
  dvec3 hy = light.half_y;
  if (!light.two_sided && glm::dot(glm::cross(hx, hy), c) >= 0.0) return 0.0;
  std::vector<dvec3> polygon{c - hx - hy, c + hx - hy, c + hx + hy, c - hx + hy};
  std::vector<dvec3> clipped;
  for (size_t i = 0; i < polygon.size(); ++i) {
    dvec3 a = polygon[i];
    dvec3 b = polygon[(i + 1) % polygon.size()];
    double da = glm::dot(n, a);
    double db = glm::dot(n, b);
    if (da >= 0.0) clipped.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) clipped.push_back(a + (b - a) * (da / (da - db)));
  }
  double sum = 0.0;
  for (size_t i = 0; i < clipped.size(); ++i) {
    dvec3 a = clipped[i];
    dvec3 b = clipped[(i + 1) % clipped.size()];
    dvec3 axb = glm::cross(a, b);
    double s = glm::length(axb);
    if (s > 0.0) sum += std::atan2(s, glm::dot(a, b)) * glm::dot(n, axb) / s;
  }
  return 0.5 * light.radiance * std::fabs(sum);
}

// Checks the value, and that the quadrature's error estimate is honest: the actual error is
// within 4 times the estimate (the whole-against-halves estimate can be fooled by the kinks of
// horizon clipping by a small factor), beyond the closed forms' own rounding (1e-12 relative,
// and 1e-13 of the scale: their terms are the light's angular size, D/R times the result).
void expect_close(const QuadratureResult& q, double exact, double scale, const char* what, int i) {
  double diff = std::fabs(q.value - exact);
  EXPECT_LE(diff, kCheck * exact + kFloor * scale) << what << " case " << i << ": " << q.value << " vs " << exact;
  EXPECT_LE(diff, 4.0 * q.error + 1e-12 * exact + 1e-13 * scale)
      << what << " case " << i << ": error estimate " << q.error;
}

void report(const char* what, long evaluations, int cases) {
  std::cout << what << ": " << evaluations / cases << " integrand evaluations per case\n";
}

TEST(AreaLightReference, SphereAboveHorizonIsPiLSin2Cos) {
  CaseGenerator g(101);
  long evaluations = 0;
  for (int i = 0; i < 300; ++i) {
    SphereLightD light = g.sphere();
    Shading s = g.shading(light.center, light.radius, light.radiance, Horizon::kAbove);
    QuadratureResult q = reference_sphere_irradiance(light, s.p, s.n, kTol);
    dvec3 d = light.center - s.p;
    double ratio = light.radius / glm::length(d);
    double exact = kPi * light.radiance * ratio * ratio * glm::dot(s.n, glm::normalize(d));
    expect_close(q, exact, s.bound_irradiance, "sphere above", i);
    evaluations += q.evaluations;
  }
  report("sphere above horizon", evaluations, 300);
}

TEST(AreaLightReference, SphereAcrossHorizonMatchesSnyder) {
  CaseGenerator g(102);
  long evaluations = 0;
  for (int i = 0; i < 300; ++i) {
    SphereLightD light = g.sphere();
    // Nearer than elsewhere too: the horizon cuts deepest into near spheres.
    Shading s = g.shading(light.center, light.radius, light.radiance, Horizon::kCrossing, dvec3(0.0), 1.02);
    QuadratureResult q = reference_sphere_irradiance(light, s.p, s.n, kTol);
    expect_close(q, sphere_exact(light, s.p, s.n), s.bound_irradiance, "sphere across", i);
    evaluations += q.evaluations;
  }
  report("sphere across horizon", evaluations, 300);
}

TEST(AreaLightReference, RectMatchesPolygonFormula) {
  CaseGenerator g(103);
  long evaluations = 0;
  for (int i = 0; i < 400; ++i) {
    RectLightD light = g.rect();
    dvec3 front = light.two_sided ? dvec3(0.0) : glm::cross(light.half_x, light.half_y);
    Horizon horizon = i % 2 ? Horizon::kCrossing : Horizon::kAbove;
    Shading s = g.shading(light.center, bounding_radius(light), light.radiance, horizon, front, 1.02);
    QuadratureResult q = reference_rect_irradiance(light, s.p, s.n, kTol);
    expect_close(q, rect_exact(light, s.p, s.n), s.bound_irradiance, "rect", i);
    evaluations += q.evaluations;
  }
  report("rectangle", evaluations, 400);
}

TEST(AreaLightReference, ZeroLengthTubeIsSphere) {
  CaseGenerator g(104);
  for (int i = 0; i < 200; ++i) {
    SphereLightD sphere = g.sphere();
    TubeLightD tube{sphere.center, sphere.center, sphere.radius, sphere.radiance};
    Horizon horizon = i % 2 ? Horizon::kCrossing : Horizon::kAbove;
    Shading s = g.shading(sphere.center, sphere.radius, sphere.radiance, horizon, dvec3(0.0), 1.02);
    QuadratureResult q = reference_tube_irradiance(tube, s.p, s.n, kTol);
    expect_close(q, sphere_exact(sphere, s.p, s.n), s.bound_irradiance, "zero-length tube", i);
  }
}

}  // namespace
}  // namespace lg
