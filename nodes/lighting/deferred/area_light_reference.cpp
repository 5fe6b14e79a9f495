#include "nodes/lighting/deferred/area_light_reference.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <numbers>
#include <utility>
#include <vector>

#include "nodes/env/brdf_lut/dfg_reference.h"

namespace lg {
namespace {

using glm::dvec3;
constexpr double kPi = std::numbers::pi;

// What every integrand needs, with the inner and outer tolerances derived from rel_tol.
struct Setting {
  dvec3 p;
  dvec3 n;
  double radiance;
  double rel_tol;
  double abs_tol;  // outer: 1e-3 rel_tol E_max
  // A weight on each direction from p (the specular lobe), none for irradiance.
  std::function<double(dvec3)> lobe = nullptr;
  // Each interval the integrands are smooth on is first cut into this many, so that the nodes of
  // the first estimates cannot all miss a lobe narrower than the light.
  int pieces = 1;

  double weight(dvec3 d) const { return lobe ? lobe(glm::normalize(d)) : 1.0; }
};

// Inner integrals are held 100 times tighter than the outer one, so their error stays a small
// part of the total; abs_tol is per unit of outer parameter, hence the division by its span.
constexpr double kInnerShare = 0.01;
// Interval budgets. An inner integrand is smooth, so an inner integral that has not converged
// in 200 intervals is at its rounding floor (n.d cancels near the horizon); the error estimate
// then reports the excess.
constexpr int kInnerIntervals = 200;
constexpr int kOuterIntervals = 1000;

Setting make_setting(dvec3 p, dvec3 n, double radiance, double rel_tol, double bounding_radius, dvec3 center,
                     const SpecularLobe* lobe) {
  double ratio = bounding_radius / glm::length(p - center);
  double e_max = kPi * radiance * std::min(1.0, ratio * ratio);
  Setting s{p, n, radiance, rel_tol, 1e-3 * rel_tol * e_max};
  if (!lobe) return s;
  // The lobe gathers at most L (its albedo is below 1), about L (R / D)^2 / alpha^2 from a light
  // smaller than it.
  const double alpha = std::max(lobe->alpha, 1e-4);
  s.abs_tol = 1e-3 * rel_tol * radiance * std::min(1.0, ratio * ratio / (alpha * alpha));
  // Cut the light's angular diameter into pieces of about the lobe's width.
  s.pieces = int(std::clamp(std::ceil(2.0 * std::asin(std::min(1.0, ratio)) / alpha), 1.0, 32.0));
  const dvec3 v = glm::normalize(lobe->v);
  const double n_dot_v = std::max(glm::dot(n, v), 1e-4);  // as brdf.glsl clamps it
  s.lobe = [n, v, n_dot_v, alpha = lobe->alpha](dvec3 l) {
    const double n_dot_l = glm::dot(n, l);
    if (!(n_dot_l > 0.0)) return 0.0;
    return ggx_specular_brdf(n_dot_v, n_dot_l, glm::dot(n, glm::normalize(l + v)), alpha);
  };
  return s;
}

void add(QuadratureResult& total, const QuadratureResult& part) {
  total.value += part.value;
  total.error += part.error;
  total.evaluations += part.evaluations;
}

// integrate_adaptive over [a, b] cut into s.pieces equal parts, abs_tol shared by length.
QuadratureResult integrate_pieces(const std::function<double(double)>& f, double a, double b, double rel_tol,
                                  double abs_tol, int max_intervals, const Setting& s) {
  QuadratureResult total;
  for (int i = 0; i < s.pieces; ++i) {
    const double lo = a + (b - a) * i / s.pieces, hi = i + 1 == s.pieces ? b : a + (b - a) * (i + 1) / s.pieces;
    add(total, integrate_adaptive(f, lo, hi, rel_tol, abs_tol / s.pieces, max_intervals));
  }
  return total;
}

// The outer integral over [s0, s1] of an inner integral that reports its own evaluations,
// split at `breaks`: where arcs appear or vanish, the inner integral has a kink of unbounded
// curvature that Gauss-Legendre handles well only at the end of an interval.
QuadratureResult outer_integral(const std::function<QuadratureResult(double, double)>& inner, double s0, double s1,
                                std::vector<double> breaks, const Setting& s) {
  double inner_abs = kInnerShare * s.abs_tol / (s1 - s0);
  long inner_evaluations = 0;
  double worst_inner = 1.0;  // the largest inner error estimate over its tolerance, if above 1
  auto outer = [&](double t) {
    QuadratureResult r = inner(t, inner_abs);
    inner_evaluations += r.evaluations;
    worst_inner = std::max(worst_inner, r.error / std::max(inner_abs, kInnerShare * s.rel_tol * std::fabs(r.value)));
    return r.value;
  };
  breaks.push_back(s0);
  breaks.push_back(s1);
  std::sort(breaks.begin(), breaks.end());
  QuadratureResult result;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    double lo = std::max(breaks[i], s0);
    double hi = std::min(breaks[i + 1], s1);
    if (hi > lo) {
      add(result, integrate_pieces(outer, lo, hi, s.rel_tol, s.abs_tol * (hi - lo) / (s1 - s0), kOuterIntervals, s));
    }
  }
  // The inner results are each within max(inner_abs, inner rel_tol |value|), or worst_inner
  // times that.
  result.error += worst_inner * kInnerShare * (s.abs_tol + s.rel_tol * std::fabs(result.value));
  result.evaluations = inner_evaluations;
  return result;
}

// An orthonormal frame about a unit axis.
struct Frame {
  dvec3 axis;
  dvec3 u;
  dvec3 v;
};

Frame frame_around(dvec3 axis) {
  dvec3 helper = std::fabs(axis.x) < 0.7 ? dvec3(1.0, 0.0, 0.0) : dvec3(0.0, 1.0, 0.0);
  dvec3 u = glm::normalize(glm::cross(helper, axis));
  return Frame{axis, u, glm::cross(axis, u)};
}

// One circle of a surface of revolution about frame.axis: points origin + rho e(phi) with
// e(phi) = cos(phi) u + sin(phi) v, outward normal axial axis + radial e(phi), and area element
// jacobian dphi per unit of the outer parameter.
struct Ring {
  dvec3 origin;
  double rho;
  double axial;
  double radial;
  double jacobian;
};

// A + B cos(phi) + C sin(phi), the form both visibility conditions take on a ring.
struct Wave {
  double a;
  double b;
  double c;
  double at(double phi) const { return a + b * std::cos(phi) + c * std::sin(phi); }
};

// The phi in [0, 2 pi) where the wave changes sign (none, or two).
void add_sign_changes(const Wave& w, std::vector<double>& cuts) {
  double amplitude = std::hypot(w.b, w.c);
  if (amplitude <= std::fabs(w.a)) return;
  double mid = std::atan2(w.c, w.b);
  double half = std::acos(-w.a / amplitude);
  for (double phi : {mid - half, mid + half}) cuts.push_back(phi - 2.0 * kPi * std::floor(phi / (2.0 * kPi)));
}

QuadratureResult ring_integral(const Ring& ring, const Frame& f, const Setting& s, double abs_tol) {
  dvec3 to_p = s.p - ring.origin;
  // Facing p: (p - x).m > 0. Above p's horizon: n.(x - p) > 0.
  Wave facing{ring.axial * glm::dot(to_p, f.axis) - ring.rho * ring.radial, ring.radial * glm::dot(to_p, f.u),
              ring.radial * glm::dot(to_p, f.v)};
  Wave above{-glm::dot(s.n, to_p), ring.rho * glm::dot(s.n, f.u), ring.rho * glm::dot(s.n, f.v)};
  std::vector<double> cuts{0.0, 2.0 * kPi};
  add_sign_changes(facing, cuts);
  add_sign_changes(above, cuts);
  std::sort(cuts.begin(), cuts.end());
  // cos(theta_p) cos(theta_l) / d^2 = (n.d)(-m.d) / d^4, d from p to the surface point.
  auto integrand = [&](double phi) {
    dvec3 e = std::cos(phi) * f.u + std::sin(phi) * f.v;
    dvec3 d = ring.origin + ring.rho * e - s.p;
    dvec3 m = ring.axial * f.axis + ring.radial * e;
    double d2 = glm::dot(d, d);
    return s.radiance * std::max(glm::dot(s.n, d), 0.0) * std::max(-glm::dot(m, d), 0.0) / (d2 * d2) * ring.jacobian *
           s.weight(d);
  };
  QuadratureResult total;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    double mid = 0.5 * (cuts[i] + cuts[i + 1]);
    if (!(cuts[i + 1] > cuts[i]) || facing.at(mid) <= 0.0 || above.at(mid) <= 0.0) continue;
    add(total, integrate_pieces(integrand, cuts[i], cuts[i + 1], kInnerShare * s.rel_tol, abs_tol, kInnerIntervals, s));
  }
  return total;
}

// A surface swept by rings for s in [s0, s1], with the kinks of the inner integral at `breaks`.
QuadratureResult rings_integral(const std::function<Ring(double)>& ring_at, const Frame& f, double s0, double s1,
                                std::vector<double> breaks, const Setting& s) {
  return outer_integral([&](double t, double abs_tol) { return ring_integral(ring_at(t), f, s, abs_tol); }, s0, s1,
                        std::move(breaks), s);
}

// The hemisphere (or, for the sphere, cap) of radius r about `center` whose pole points along
// frame.axis, by polar angle g.
QuadratureResult cap_integral(dvec3 center, double r, const Frame& f, double max_angle, const Setting& s) {
  auto ring_at = [&](double g) {
    return Ring{center + r * std::cos(g) * f.axis, r * std::sin(g), std::cos(g), std::sin(g), r * r * std::sin(g)};
  };
  // Arcs appear or vanish where a ring touches the horizon plane or the facing boundary: where
  // a wave's constant term equals +-its amplitude, each a k0 + k1 cos g + k2 sin g = 0.
  dvec3 to_c = center - s.p;
  double n_across = std::hypot(glm::dot(s.n, f.u), glm::dot(s.n, f.v));
  double p_along = -glm::dot(to_c, f.axis);
  double p_across = std::hypot(glm::dot(to_c, f.u), glm::dot(to_c, f.v));
  std::vector<double> breaks;
  for (double sign : {-1.0, 1.0}) {
    add_sign_changes(Wave{glm::dot(s.n, to_c), r * glm::dot(s.n, f.axis), sign * r * n_across}, breaks);
    add_sign_changes(Wave{-r, p_along, sign * p_across}, breaks);
  }
  return rings_integral(ring_at, f, 0.0, max_angle, std::move(breaks), s);
}

QuadratureResult sphere_integral(const SphereLightD& light, dvec3 p, dvec3 n, double rel_tol,
                                 const SpecularLobe* lobe) {
  dvec3 to_p = p - light.center;
  double dist = glm::length(to_p);
  double r = light.radius;
  if (!(r > 0.0) || !(dist > r)) return {};
  // The part facing p is the cap about the direction to p out to cos(angle) = r / dist.
  Setting s = make_setting(p, n, light.radiance, rel_tol, r, light.center, lobe);
  return cap_integral(light.center, r, frame_around(to_p / dist), std::acos(r / dist), s);
}

QuadratureResult tube_integral(const TubeLightD& light, dvec3 p, dvec3 n, double rel_tol, const SpecularLobe* lobe) {
  double r = light.radius;
  dvec3 along = light.end1 - light.end0;
  double len = glm::length(along);
  dvec3 axis = len > 0.0 ? along / len : dvec3(0.0, 0.0, 1.0);
  double t = std::clamp(glm::dot(p - light.end0, axis), 0.0, len);
  if (!(r > 0.0) || !(glm::length(p - (light.end0 + t * axis)) > r)) return {};
  Setting s = make_setting(p, n, light.radiance, rel_tol, 0.5 * len + r, 0.5 * (light.end0 + light.end1), lobe);
  Frame f = frame_around(axis);
  QuadratureResult total = cap_integral(light.end1, r, f, 0.5 * kPi, s);
  add(total, cap_integral(light.end0, r, Frame{-f.axis, f.u, f.v}, 0.5 * kPi, s));
  if (len > 0.0) {
    auto ring_at = [&](double z) { return Ring{light.end0 + z * axis, r, 0.0, 1.0, r}; };
    // Rings touch the horizon plane where n.(ring center - p) = +-r |n across the axis|; whether
    // a ring faces p does not depend on z.
    double n_along = glm::dot(n, axis);
    double n_across = std::sqrt(std::max(0.0, 1.0 - n_along * n_along));
    std::vector<double> breaks;
    if (n_along != 0.0) {
      for (double sign : {-1.0, 1.0}) breaks.push_back((sign * r * n_across - glm::dot(n, light.end0 - p)) / n_along);
    }
    add(total, rings_integral(ring_at, f, 0.0, len, std::move(breaks), s));
  }
  return total;
}

QuadratureResult rect_integral(const RectLightD& light, dvec3 p, dvec3 n, double rel_tol, const SpecularLobe* lobe) {
  dvec3 normal = glm::cross(light.half_x, light.half_y);
  double jacobian = glm::length(normal);  // dA = |half_x x half_y| ds dt over [-1, 1]^2
  if (!(jacobian > 0.0)) return {};
  dvec3 nl = normal / jacobian;
  double front = glm::dot(p - light.center, nl);
  if (front == 0.0 || (!light.two_sided && !(front > 0.0))) return {};
  double bounding = std::sqrt(glm::dot(light.half_x, light.half_x) + glm::dot(light.half_y, light.half_y));
  Setting s = make_setting(p, n, light.radiance, rel_tol, bounding, light.center, lobe);
  // Row s: x = center + s half_x + t half_y, above the horizon where base + t slope > 0.
  auto row = [&](double sx, double abs_tol) {
    dvec3 origin = light.center + sx * light.half_x;
    double base = glm::dot(n, origin - p);
    double slope = glm::dot(n, light.half_y);
    double lo = -1.0;
    double hi = 1.0;
    if (slope > 0.0) lo = std::max(lo, -base / slope);
    if (slope < 0.0) hi = std::min(hi, -base / slope);
    if (slope == 0.0 && !(base > 0.0)) return QuadratureResult{};
    if (!(hi > lo)) return QuadratureResult{};
    auto integrand = [&](double ty) {
      dvec3 d = origin + ty * light.half_y - p;
      double d2 = glm::dot(d, d);
      return s.radiance * std::max(glm::dot(n, d), 0.0) * std::fabs(glm::dot(nl, d)) / (d2 * d2) * jacobian *
             s.weight(d);
    };
    return integrate_pieces(integrand, lo, hi, kInnerShare * s.rel_tol, abs_tol, kInnerIntervals, s);
  };
  // The clipped row's length has a kink where the horizon line crosses a corner (t = +-1).
  double base0 = glm::dot(n, light.center - p);
  double along_x = glm::dot(n, light.half_x);
  double along_y = glm::dot(n, light.half_y);
  std::vector<double> breaks;
  if (along_x != 0.0) {
    for (double sign : {-1.0, 1.0}) breaks.push_back(-(base0 + sign * along_y) / along_x);
  }
  return outer_integral(row, -1.0, 1.0, std::move(breaks), s);
}

}  // namespace

QuadratureResult reference_sphere_irradiance(const SphereLightD& light, dvec3 p, dvec3 n, double rel_tol) {
  return sphere_integral(light, p, n, rel_tol, nullptr);
}

QuadratureResult reference_tube_irradiance(const TubeLightD& light, dvec3 p, dvec3 n, double rel_tol) {
  return tube_integral(light, p, n, rel_tol, nullptr);
}

QuadratureResult reference_rect_irradiance(const RectLightD& light, dvec3 p, dvec3 n, double rel_tol) {
  return rect_integral(light, p, n, rel_tol, nullptr);
}

QuadratureResult reference_sphere_specular(const SphereLightD& light, dvec3 p, dvec3 n, const SpecularLobe& lobe,
                                           double rel_tol) {
  return sphere_integral(light, p, glm::normalize(n), rel_tol, &lobe);
}

QuadratureResult reference_tube_specular(const TubeLightD& light, dvec3 p, dvec3 n, const SpecularLobe& lobe,
                                         double rel_tol) {
  return tube_integral(light, p, glm::normalize(n), rel_tol, &lobe);
}

QuadratureResult reference_rect_specular(const RectLightD& light, dvec3 p, dvec3 n, const SpecularLobe& lobe,
                                         double rel_tol) {
  return rect_integral(light, p, glm::normalize(n), rel_tol, &lobe);
}

}  // namespace lg
