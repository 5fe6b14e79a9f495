#include "nodes/gi/path_tracer/path_lights.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "nodes/raytrace/cosine_sampling.h"

namespace lg {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A direction in the cone about unit `axis` whose 1 - cos(half angle) is `one_minus_cos`,
// uniform in solid angle.
glm::dvec3 sample_cone(glm::dvec3 axis, double one_minus_cos, glm::dvec2 u) {
  const double one_minus_z = u.x * one_minus_cos;
  const double z = 1.0 - one_minus_z;
  const double r = std::sqrt(std::max(0.0, one_minus_z * (2.0 - one_minus_z)));
  const double phi = 2.0 * kPi * u.y;
  return glm::normalize(make_frame(axis).to_world({r * std::cos(phi), r * std::sin(phi), z}));
}

double cone_pdf(double one_minus_cos) {
  return 1.0 / (2.0 * kPi * one_minus_cos);
}

// 1 - cos of the half angle a sphere of radius r subtends at distance d > r, without
// cancellation for small spheres.
double sphere_one_minus_cos(double r, double d) {
  const double sin2 = (r * r) / (d * d);
  return sin2 / (1.0 + std::sqrt(std::max(0.0, 1.0 - sin2)));
}

// The nearer intersection distance of a ray from outside a sphere, or infinity.
double enter_sphere(glm::dvec3 o, glm::dvec3 d, glm::dvec3 c, double r) {
  const glm::dvec3 oc = c - o;
  const double b = glm::dot(d, oc), cc = glm::dot(oc, oc) - r * r;
  const double disc = b * b - cc;
  if (cc <= 0.0 || b <= 0.0 || disc < 0.0) return kInfinity;
  return b - std::sqrt(disc);
}

glm::dvec3 closest_on_segment(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + s * ab;
}

// Where a ray from outside a capsule first meets it: the first entry into the union of its
// cylinder (the side; an entry through a flat end lies inside an end ball) and its two balls.
double enter_capsule(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b, double r) {
  double t = std::min(enter_sphere(o, d, a, r), enter_sphere(o, d, b, r));
  const glm::dvec3 axis = b - a;
  const double length = glm::length(axis);
  if (length > 0.0) {
    const glm::dvec3 w = axis / length;
    const glm::dvec3 d_perp = d - glm::dot(d, w) * w, o_perp = (o - a) - glm::dot(o - a, w) * w;
    const double qa = glm::dot(d_perp, d_perp), qb = 2.0 * glm::dot(d_perp, o_perp);
    const double qc = glm::dot(o_perp, o_perp) - r * r;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (qa > 0.0 && disc >= 0.0) {
      const double t0 = (-qb - std::sqrt(disc)) / (2.0 * qa);
      const double s = glm::dot(o + t0 * d - a, w);
      if (t0 > 0.0 && s >= 0.0 && s <= length) t = std::min(t, t0);
    }
  }
  return t;
}

}  // namespace

PathLights::PathLights(const SceneView& view, std::vector<DistantDisk> distant_disks) {
  auto add_distant = [&](glm::dvec3 toward, double angular_radius, glm::dvec3 irradiance_or_radiance, bool scene) {
    Light l{Kind::distant};
    l.scene_light = scene;
    l.a = glm::normalize(toward);
    const double half = 0.5 * std::max(angular_radius, 0.0);
    l.size = 2.0 * std::sin(half) * std::sin(half);  // 1 - cos(angular radius)
    l.radiance = irradiance_or_radiance;
    lights_.push_back(l);
  };
  for (const DirectionalLightData& d : view.directional_lights) {
    const double a = std::max(double(d.angular_radius), 0.0);
    const double sin_a = std::sin(std::min(a, kPi / 2));
    // A uniform disk of angular radius a gives E = L pi sin^2 a to a surface facing it.
    add_distant(-glm::dvec3(d.direction), a,
                a > 0.0 ? glm::dvec3(d.irradiance) / (kPi * sin_a * sin_a) : glm::dvec3(d.irradiance), true);
  }
  for (const DistantDisk& d : distant_disks) add_distant(d.toward, d.angular_radius, d.radiance, false);
  for (const PointLightData& p : view.point_lights) {
    Light l{Kind::point};
    l.a = glm::dvec3(p.position), l.radiance = glm::dvec3(p.intensity), l.size = p.range;
    lights_.push_back(l);
  }
  for (const SpotLightData& spot : view.spot_lights) {
    Light l{Kind::point};
    l.a = glm::dvec3(spot.position), l.b = glm::normalize(glm::dvec3(spot.direction));
    l.radiance = glm::dvec3(spot.intensity), l.size = spot.range;
    // lighting.deferred's cone (deferred_kernel.cpp): 0 at the outer cone, 1 from the inner one in.
    const double cos_outer = std::cos(double(spot.outer_cone_angle));
    l.cone_scale = 1.0 / std::max(0.001, std::cos(double(spot.inner_cone_angle)) - cos_outer);
    l.cone_offset = -cos_outer * l.cone_scale;
    lights_.push_back(l);
  }
  for (const SphereLightData& s : view.sphere_lights) {
    Light l{Kind::sphere};
    l.a = glm::dvec3(s.center), l.radiance = glm::dvec3(s.radiance), l.size = s.radius;
    if (s.radius > 0.0f) lights_.push_back(l);
  }
  for (const TubeLightData& t : view.tube_lights) {
    Light l{Kind::tube};
    l.a = glm::dvec3(t.end0), l.b = glm::dvec3(t.end1), l.radiance = glm::dvec3(t.radiance), l.size = t.radius;
    const double r = t.radius;
    l.area = 2.0 * kPi * r * glm::length(l.b - l.a) + 4.0 * kPi * r * r;
    if (l.area > 0.0) lights_.push_back(l);
  }
  for (const RectLightData& q : view.rect_lights) {
    Light l{Kind::rect};
    l.a = glm::dvec3(q.center), l.b = glm::dvec3(q.half_x), l.c = glm::dvec3(q.half_y);
    l.radiance = glm::dvec3(q.radiance), l.two_sided = q.two_sided;
    l.area = 4.0 * glm::length(glm::cross(l.b, l.c));
    if (l.area > 0.0) lights_.push_back(l);
  }
}

std::optional<LightSample> PathLights::sample(size_t i, glm::dvec3 p, glm::dvec2 u) const {
  const Light& l = lights_[i];
  switch (l.kind) {
    case Kind::distant:
      return sample_distant(l, u);
    case Kind::point: {
      const glm::dvec3 to = l.a - p;
      const double d2 = glm::dot(to, to);
      if (!(d2 > 1e-16)) return std::nullopt;
      const double range = l.size;
      // The deferred node's window (Karis 2013): smooth to 0 at the range.
      const double x = 1.0 - std::pow(d2 / (range * range), 2.0);
      const double window = range > 0.0 ? std::pow(std::clamp(x, 0.0, 1.0), 2.0) : 1.0;
      const double d = std::sqrt(d2);
      const double ramp = std::clamp(glm::dot(l.b, -to / d) * l.cone_scale + l.cone_offset, 0.0, 1.0);
      return LightSample{to / d, d, l.radiance * (window * ramp * ramp / d2), 0.0};
    }
    case Kind::sphere:
      return sample_sphere(l, p, u);
    case Kind::tube:
      return sample_tube(l, p, u);
    case Kind::rect:
      return sample_rect(l, p, u);
  }
  return std::nullopt;
}

std::optional<LightSample> PathLights::sample_distant(const Light& l, glm::dvec2 u) const {
  if (!(l.size > 0.0)) return LightSample{l.a, kInfinity, l.radiance, 0.0};
  const double pdf = cone_pdf(l.size);
  return LightSample{sample_cone(l.a, l.size, u), kInfinity, l.radiance / pdf, pdf};
}

std::optional<LightSample> PathLights::sample_sphere(const Light& l, glm::dvec3 p, glm::dvec2 u) const {
  const glm::dvec3 to = l.a - p;
  const double d = glm::length(to), r = l.size;
  if (!(d > r)) return std::nullopt;  // inside the light: no sensible answer
  const double omc = sphere_one_minus_cos(r, d);
  const glm::dvec3 direction = sample_cone(to / d, omc, u);
  const double t = enter_sphere(p, direction, l.a, r);
  const double pdf = cone_pdf(omc);
  // A direction at the cone's rim may graze past through rounding; the tangent point is as far.
  const double distance = std::isfinite(t) ? t : std::sqrt(std::max(0.0, d * d - r * r));
  return LightSample{direction, distance, l.radiance / pdf, pdf};
}

std::optional<LightSample> PathLights::sample_tube(const Light& l, glm::dvec3 p, glm::dvec2 u) const {
  const double r = l.size;
  if (glm::length(p - closest_on_segment(p, l.a, l.b)) <= r) return std::nullopt;
  const glm::dvec3 axis = l.b - l.a;
  const double length = glm::length(axis);
  const Frame frame = make_frame(length > 0.0 ? axis / length : glm::dvec3(0.0, 0.0, 1.0));
  const double cylinder_share = 2.0 * kPi * r * length / l.area;
  glm::dvec3 point, normal;
  if (u.x < cylinder_share) {
    const double s = u.x / cylinder_share * length, phi = 2.0 * kPi * u.y;
    normal = frame.tangent * std::cos(phi) + frame.bitangent * std::sin(phi);
    point = l.a + frame.normal * s + r * normal;
  } else {  // a uniform point of a sphere, its half toward end0 around end0, the other around end1
    const double z = 1.0 - 2.0 * (u.x - cylinder_share) / (1.0 - cylinder_share);
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u.y;
    normal = frame.to_world({rho * std::cos(phi), rho * std::sin(phi), z});
    point = (z < 0.0 ? l.a : l.b) + r * normal;
  }
  const glm::dvec3 to = point - p;
  const double d = glm::length(to);
  const double cos_light = -glm::dot(normal, to) / d;
  if (!(cos_light > 0.0)) return std::nullopt;  // the far side: hidden behind the capsule itself
  const double pdf = d * d / (l.area * cos_light);
  return LightSample{to / d, d, l.radiance / pdf, pdf};
}

std::optional<LightSample> PathLights::sample_rect(const Light& l, glm::dvec3 p, glm::dvec2 u) const {
  const glm::dvec3 point = l.a + (2.0 * u.x - 1.0) * l.b + (2.0 * u.y - 1.0) * l.c;
  const glm::dvec3 normal = glm::normalize(glm::cross(l.b, l.c));
  const glm::dvec3 to = point - p;
  const double d = glm::length(to);
  if (!(d > 0.0)) return std::nullopt;
  double cos_light = -glm::dot(normal, to) / d;
  if (l.two_sided) cos_light = std::abs(cos_light);
  if (!(cos_light > 0.0)) return std::nullopt;
  const double pdf = d * d / (l.area * cos_light);
  return LightSample{to / d, d, l.radiance / pdf, pdf};
}

void PathLights::each_crossed(glm::dvec3 o, glm::dvec3 d, double t_max,
                              const std::function<void(size_t, const LightCrossing&)>& f) const {
  for (size_t i = 0; i < lights_.size(); ++i) {
    const Light& l = lights_[i];
    switch (l.kind) {
      case Kind::distant:
        if (std::isinf(t_max) && l.size > 0.0 && 1.0 - glm::dot(d, l.a) <= l.size) f(i, {l.radiance, cone_pdf(l.size)});
        break;
      case Kind::point:
        break;  // a delta light is never met
      case Kind::sphere: {
        const double t = enter_sphere(o, d, l.a, l.size);
        if (t <= t_max) f(i, {l.radiance, cone_pdf(sphere_one_minus_cos(l.size, glm::length(l.a - o)))});
        break;
      }
      case Kind::tube: {
        if (glm::length(o - closest_on_segment(o, l.a, l.b)) <= l.size) break;
        const double t = enter_capsule(o, d, l.a, l.b, l.size);
        if (!(t <= t_max)) break;
        const glm::dvec3 q = o + t * d;
        const glm::dvec3 normal = glm::normalize(q - closest_on_segment(q, l.a, l.b));
        const double cos_light = std::abs(glm::dot(normal, d));
        if (cos_light > 0.0) f(i, {l.radiance, t * t / (l.area * cos_light)});
        break;
      }
      case Kind::rect: {
        const glm::dvec3 n = glm::cross(l.b, l.c);
        const glm::dvec3 normal = glm::normalize(n);
        const double denom = glm::dot(d, normal);
        if (denom == 0.0 || (!l.two_sided && denom > 0.0)) break;  // edge-on, or the dark back
        const double t = glm::dot(l.a - o, normal) / denom;
        if (!(t > 0.0) || t > t_max) break;
        const glm::dvec3 q = o + t * d - l.a;
        // Coordinates along the half axes by the dual basis (the axes need not be orthogonal).
        const double x = glm::dot(q, glm::cross(l.c, n)) / glm::dot(l.b, glm::cross(l.c, n));
        const double y = glm::dot(q, glm::cross(n, l.b)) / glm::dot(l.c, glm::cross(n, l.b));
        if (std::abs(x) <= 1.0 && std::abs(y) <= 1.0) f(i, {l.radiance, t * t / (l.area * std::abs(denom))});
        break;
      }
    }
  }
}

}  // namespace lg
