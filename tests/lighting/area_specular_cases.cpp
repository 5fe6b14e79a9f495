#include "tests/lighting/area_specular_cases.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "nodes/env/brdf_lut/dfg_reference.h"
#include "nodes/lighting/deferred/area_light_ltc.h"
#include "nodes/lighting/deferred/area_light_specular.h"
#include "nodes/lighting/deferred/ltc_table.h"

namespace lg {

using glm::dvec3;

const char* shape_name(LightShape shape) {
  switch (shape) {
    case LightShape::kSphere:
      return "sphere";
    case LightShape::kTube:
      return "tube";
    case LightShape::kRect:
      return "rectangle";
  }
  return "?";
}

SpecularCase make_specular_case(CaseGenerator& g, LightShape shape, const SpecularRange& range) {
  SpecularCase c{};
  c.shape = shape;
  c.horizon = range.horizon;
  dvec3 center, front(0.0);
  double bound = 0.0, radiance = 0.0;
  if (shape == LightShape::kSphere) {
    c.sphere = rounded(g.sphere());
    center = c.sphere.center, bound = bounding_radius(c.sphere), radiance = c.sphere.radiance;
  } else if (shape == LightShape::kTube) {
    c.tube = rounded(g.tube());
    center = light_center(c.tube), bound = bounding_radius(c.tube), radiance = c.tube.radiance;
  } else {
    c.rect = rounded(g.rect());
    center = c.rect.center, bound = bounding_radius(c.rect), radiance = c.rect.radiance;
    if (!c.rect.two_sided) front = glm::cross(c.rect.half_x, c.rect.half_y);
  }
  const Shading s = g.shading(center, bound, radiance, range.horizon, front, range.min_distance, range.max_distance);
  c.p = dvec3(to_float(s.p));
  c.n = glm::normalize(dvec3(to_float(s.n)));
  c.distance = glm::length(c.p - center) / bound;
  // A view at n.v uniform in [min, 1], turned about n at random.
  const double n_dot_v = g.uniform(range.min_n_dot_v, 1.0);
  const dvec3 t = glm::normalize(glm::cross(c.n, g.direction()));
  c.v = glm::normalize(dvec3(to_float(n_dot_v * c.n + std::sqrt(1.0 - n_dot_v * n_dot_v) * t)));
  c.roughness = float(g.uniform(range.min_roughness, range.max_roughness));
  return c;
}

namespace {

// area_lights.glsl's area_specular: the point shaded as a point light of intensity L x `area`.
double point_light_specular(const SpecularCase& c, const RepresentativePoint& rp, double radiance, double area,
                            double alpha) {
  if (!(rp.normalization > 0.0f)) return 0.0;
  const dvec3 l = glm::normalize(dvec3(rp.direction));
  const double n_dot_l = glm::dot(c.n, l);
  if (!(n_dot_l > 0.0)) return 0.0;
  const double n_dot_v = std::max(glm::dot(c.n, c.v), 1e-4);
  const double d2 = std::max(double(rp.distance) * rp.distance, 1e-8);
  return ggx_specular_brdf(n_dot_v, n_dot_l, glm::dot(c.n, glm::normalize(l + c.v)), alpha) * n_dot_l * radiance *
         area / d2 * rp.normalization;
}

}  // namespace

SpecularSample evaluate_specular(const SpecularCase& c, double rel_tol) {
  const double alpha = ltc_alpha(c.roughness);
  const SpecularLobe lobe{c.v, alpha};
  const double n_dot_v = std::max(glm::dot(c.n, c.v), 1e-4);
  const glm::dvec2 ab = brdf_albedo_lookup(n_dot_v, c.roughness);
  const LtcLobe ltc = ltc_lobe(float(n_dot_v), float(c.roughness));
  const glm::vec3 p = to_float(c.p), n = to_float(c.n), v = to_float(c.v);
  const glm::vec3 r = glm::normalize(2.0f * glm::dot(n, v) * n - v);
  SpecularSample s{};
  if (c.shape == LightShape::kSphere) {
    const SphereLight l = to_float(c.sphere);
    s.reference = reference_sphere_specular(c.sphere, c.p, c.n, lobe, rel_tol).value;
    s.ltc = ltc_sphere_specular(l, p, n, v, ltc);
    s.representative_point = point_light_specular(c, sphere_specular_point(l, p, r, float(alpha)), l.radiance,
                                                  std::numbers::pi * l.radius * l.radius, alpha);
    s.albedo = l.radiance;
  } else if (c.shape == LightShape::kTube) {
    const TubeLight l = to_float(c.tube);
    s.reference = reference_tube_specular(c.tube, c.p, c.n, lobe, rel_tol).value;
    s.ltc = ltc_tube_specular(l, p, n, v, ltc);
    const RepresentativePoint rp = tube_specular_point(l, p, r, float(alpha));
    // As area_lights.glsl: the caps' disc and the cylinder's length x diameter seen from the side.
    const dvec3 axis = dvec3(l.end1 - l.end0);
    const double len = glm::length(axis);
    const double sin_side = len > 0.0 ? glm::length(glm::cross(axis / len, dvec3(rp.direction))) : 0.0;
    s.representative_point = point_light_specular(
        c, rp, l.radiance, std::numbers::pi * l.radius * l.radius + 2.0 * l.radius * len * sin_side, alpha);
    s.albedo = l.radiance;
  } else {
    const RectLight l = to_float(c.rect);
    s.reference = reference_rect_specular(c.rect, c.p, c.n, lobe, rel_tol).value;
    s.ltc = ltc_rect_specular(l, p, n, v, ltc);
    const RepresentativePoint rp = rect_specular_point(l, p, r, float(alpha));
    const dvec3 normal = glm::cross(dvec3(l.half_x), dvec3(l.half_y));
    const double facing = std::fabs(glm::dot(glm::normalize(normal), dvec3(rp.direction)));
    s.representative_point = point_light_specular(c, rp, l.radiance, 4.0 * glm::length(normal) * facing, alpha);
    s.albedo = l.radiance;
  }
  s.ltc *= ab.x + ab.y;
  s.albedo *= ab.x + ab.y;
  // As area_lights.glsl's area_specular bounds it: at most what the whole lobe reflects.
  s.representative_point = std::min(s.representative_point, s.albedo);
  return s;
}

namespace {

SpecularErrors errors(const std::vector<SpecularSample>& samples, double SpecularSample::*method) {
  SpecularErrors e;
  if (samples.empty()) return e;
  double sum_sq = 0.0, sum_ref = 0.0, sum_pointwise = 0.0;
  for (const SpecularSample& s : samples) {
    const double diff = (s.*method - s.reference) / s.albedo;
    sum_sq += diff * diff;
    sum_ref += s.reference / s.albedo;
    if (s.reference >= kLitShare * s.albedo) {
      const double rel = (s.*method - s.reference) / s.reference;
      sum_pointwise += rel * rel;
      e.max_pointwise = std::max(e.max_pointwise, std::fabs(rel));
      ++e.lit;
    }
  }
  const double n = double(samples.size());
  e.relative_rms = std::sqrt(sum_sq / n) / (sum_ref / n);
  e.pointwise_rms = e.lit > 0 ? std::sqrt(sum_pointwise / e.lit) : 0.0;
  return e;
}

}  // namespace

SpecularErrors ltc_errors(const std::vector<SpecularSample>& samples) {
  return errors(samples, &SpecularSample::ltc);
}

SpecularErrors representative_point_errors(const std::vector<SpecularSample>& samples) {
  return errors(samples, &SpecularSample::representative_point);
}

}  // namespace lg
