#include "tests/lighting/area_light_cases.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {

using glm::dvec3;

double CaseGenerator::log_uniform(double lo, double hi) {
  return std::exp(uniform(std::log(lo), std::log(hi)));
}

dvec3 CaseGenerator::direction() {
  std::normal_distribution<double> normal;
  dvec3 d;
  do d = dvec3(normal(rng_), normal(rng_), normal(rng_));
  while (glm::dot(d, d) < 1e-6);
  return glm::normalize(d);
}

namespace {

dvec3 random_point(CaseGenerator& g) {
  return dvec3(g.uniform(-10, 10), g.uniform(-10, 10), g.uniform(-10, 10));
}

}  // namespace

SphereLightD CaseGenerator::sphere() {
  return SphereLightD{random_point(*this), log_uniform(0.05, 2.0), log_uniform(0.1, 1000.0)};
}

TubeLightD CaseGenerator::tube() {
  dvec3 end0 = random_point(*this);
  double length = log_uniform(0.1, 4.0);
  return TubeLightD{end0, end0 + length * direction(), log_uniform(0.02, 0.5), log_uniform(0.1, 1000.0)};
}

RectLightD CaseGenerator::rect() {
  dvec3 x = direction();
  dvec3 y = glm::normalize(glm::cross(x, direction()));
  return RectLightD{random_point(*this), log_uniform(0.05, 2.0) * x, log_uniform(0.05, 2.0) * y,
                    log_uniform(0.1, 1000.0), uniform(0, 1) < 0.5};
}

Shading CaseGenerator::shading(dvec3 center, double bounding_radius, double radiance, Horizon horizon, dvec3 front,
                               double min_distance, double max_distance) {
  dvec3 away = direction();
  if (glm::dot(away, front) < 0.0) away = -away;
  double dist = bounding_radius * log_uniform(min_distance, max_distance);
  dvec3 p = center + dist * away;
  // Tilt n from the direction to the center by theta: the bounding sphere spans beta either
  // side of that direction, so theta <= pi/2 - beta keeps it all above the horizon.
  double beta = std::asin(bounding_radius / dist);
  double theta = horizon == Horizon::kAbove ? std::acos(uniform(std::sin(beta), 1.0))
                                            : uniform(std::numbers::pi / 2 - beta, std::numbers::pi / 2 + beta);
  dvec3 toward = -away;
  dvec3 side = glm::normalize(glm::cross(toward, direction()));
  dvec3 n = std::cos(theta) * toward + std::sin(theta) * side;
  double ratio = bounding_radius / dist;
  return Shading{p, glm::normalize(n), std::numbers::pi * radiance * ratio * ratio};
}

double bounding_radius(const SphereLightD& light) {
  return light.radius;
}
double bounding_radius(const TubeLightD& light) {
  return 0.5 * glm::length(light.end1 - light.end0) + light.radius;
}
double bounding_radius(const RectLightD& light) {
  return std::sqrt(glm::dot(light.half_x, light.half_x) + glm::dot(light.half_y, light.half_y));
}
dvec3 light_center(const SphereLightD& light) {
  return light.center;
}
dvec3 light_center(const TubeLightD& light) {
  return 0.5 * (light.end0 + light.end1);
}
dvec3 light_center(const RectLightD& light) {
  return light.center;
}

glm::vec3 to_float(dvec3 v) {
  return glm::vec3(v);
}
SphereLight to_float(const SphereLightD& l) {
  return SphereLight{to_float(l.center), float(l.radius), float(l.radiance)};
}
TubeLight to_float(const TubeLightD& l) {
  return TubeLight{to_float(l.end0), to_float(l.end1), float(l.radius), float(l.radiance)};
}
RectLight to_float(const RectLightD& l) {
  return RectLight{to_float(l.center), to_float(l.half_x), to_float(l.half_y), float(l.radiance), l.two_sided};
}

SphereLightD rounded(const SphereLightD& l) {
  SphereLight f = to_float(l);
  return SphereLightD{dvec3(f.center), f.radius, f.radiance};
}
TubeLightD rounded(const TubeLightD& l) {
  TubeLight f = to_float(l);
  return TubeLightD{dvec3(f.end0), dvec3(f.end1), f.radius, f.radiance};
}
RectLightD rounded(const RectLightD& l) {
  RectLight f = to_float(l);
  return RectLightD{dvec3(f.center), dvec3(f.half_x), dvec3(f.half_y), f.radiance, f.two_sided};
}

}  // namespace lg
