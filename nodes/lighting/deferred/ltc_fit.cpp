#include "nodes/lighting/deferred/ltc_fit.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>
#include <vector>

#include "nodes/env/brdf_lut/dfg_reference.h"
#include "nodes/lighting/deferred/area_light_ltc.h"
#include "nodes/lighting/deferred/ltc_table.h"
#include "nodes/lighting/deferred/nelder_mead.h"

namespace lg {
namespace {

using glm::dvec3;
constexpr double kPi = std::numbers::pi;
constexpr int kGrid = 32;  // samples per axis of each of the objective's two grids

struct Lobe {
  dvec3 v;
  double n_dot_v;
  double alpha;

  double value(dvec3 l) const {  // f (n.l), Fresnel 1
    if (!(l.z > 0.0)) return 0.0;
    const dvec3 h = glm::normalize(v + l);
    return ggx_specular_brdf(n_dot_v, l.z, h.z, alpha) * l.z;
  }

  // A direction by GGX's distribution of normals D(h) (n.h), and its density over l.
  dvec3 sample(double u1, double u2, double& pdf) const {
    const double phi = 2.0 * kPi * u2;
    const double cos_h = 1.0 / std::sqrt(1.0 + alpha * alpha * u1 / (1.0 - u1));
    const double sin_h = std::sqrt(std::max(0.0, 1.0 - cos_h * cos_h));
    const dvec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
    const double v_dot_h = glm::dot(v, h);
    const double a2 = alpha * alpha, d = cos_h * cos_h * (a2 - 1.0) + 1.0;
    pdf = a2 / (kPi * d * d) * cos_h / (4.0 * std::fabs(v_dot_h));
    return 2.0 * v_dot_h * h - v;
  }
};

double grid_u(int k) {
  return (k + 0.5) / kGrid;
}

// The L1 distance of the normalised lobe and the LTC of transform m (above).
double fit_error(const Lobe& lobe, double norm, const glm::dmat3& m) {
  const glm::dmat3 m_inv = glm::inverse(m);
  double error = 0.0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double u1 = grid_u(i), u2 = grid_u(j);
      // From the LTC: a cosine-distributed direction through M.
      {
        const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
        const dvec3 l = glm::normalize(m * dvec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)));
        double pdf_lobe = 0.0;
        const double lobe_value = lobe.value(l) / norm;
        // The density the lobe's sampler has at l: that of its half vector.
        const dvec3 h = glm::normalize(lobe.v + l);
        const double a2 = lobe.alpha * lobe.alpha, d = h.z * h.z * (a2 - 1.0) + 1.0;
        const double v_dot_h = std::fabs(glm::dot(lobe.v, h));
        pdf_lobe = h.z > 0.0 && v_dot_h > 0.0 ? a2 / (kPi * d * d) * h.z / (4.0 * v_dot_h) : 0.0;
        const double ltc = ltc_density(m_inv, l);
        error += std::fabs(lobe_value - ltc) / (pdf_lobe + ltc);
      }
      // From the lobe.
      {
        double pdf_lobe = 0.0;
        const dvec3 l = lobe.sample(u1, u2, pdf_lobe);
        const double lobe_value = lobe.value(l) / norm;
        const double ltc = ltc_density(m_inv, l);
        if (pdf_lobe + ltc > 0.0) error += std::fabs(lobe_value - ltc) / (pdf_lobe + ltc);
      }
    }
  }
  return error / (kGrid * kGrid);
}

glm::dmat3 transform(const glm::dmat3& frame, const std::vector<double>& x) {
  // Columns: (a, 0, 0), (0, c, 0), (b, 0, 1).
  return frame * glm::dmat3(dvec3(x[0], 0.0, x[3]), dvec3(0.0, x[1], 0.0), dvec3(x[2], 0.0, 1.0));
}

// M^-1 scaled to a middle element of 1, as the table stores it.
glm::dvec4 table_entry(const glm::dmat3& m) {
  const glm::dmat3 inv = glm::inverse(m);
  // (row, column) = [column][row] in glm.
  return glm::dvec4(inv[0][0], inv[2][0], inv[0][2], inv[2][2]) / inv[1][1];
}

// A cone of directions: unit axis and half-angle.
struct Cap {
  dvec3 axis;
  double half_angle;
};

dvec3 direction(double theta, double phi) {
  return dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// The caps whose integrals the second stage matches (the lobe is symmetric about y = 0, so
// azimuths 0 to pi): lights of every size the benchmark has, 1.5 to 50 bounding radii away
// (half-angles 1 to 42 degrees), centred over the hemisphere and across its horizon, and caps
// the size of the lobe around its peak, where a sharp lobe's light is.
std::vector<Cap> fit_caps(dvec3 peak, double alpha) {
  std::vector<Cap> caps;
  const double deg = kPi / 180.0;
  for (double half_angle : {3.0 * deg, 8.0 * deg, 20.0 * deg, 40.0 * deg}) {
    for (int t = 0; t < 8; ++t) {
      const double theta = (5.0 + 12.0 * t) * deg;  // 5 to 89 degrees
      if (theta - half_angle >= 0.5 * kPi) continue;
      for (int a = 0; a < 5; ++a) caps.push_back({direction(theta, kPi * a / 4.0), half_angle});
    }
  }
  const double width = std::max(std::atan(alpha), 0.5 * deg);
  const dvec3 side = glm::normalize(glm::cross(dvec3(0.0, 1.0, 0.0), peak));
  for (double scale : {0.5, 1.0, 2.0}) {
    for (double offset : {-2.0, -1.0, 0.0, 1.0, 2.0})
      caps.push_back({glm::normalize(peak + std::tan(offset * width) * side), scale * width});
    caps.push_back({glm::normalize(peak + std::tan(width) * dvec3(0.0, 1.0, 0.0)), scale * width});
  }
  return caps;
}

bool in_cap(const Cap& cap, dvec3 l) {
  return glm::dot(cap.axis, l) > std::cos(cap.half_angle);
}

// The LTC's integral over a cap (clipped to the horizon as the shaders clip): its circle on the
// plane at distance 1 along the axis as a polygon of the same area.
double ltc_cap_integral(const LtcPolygon& start, const Cap& cap) {
  constexpr int kSides = 12;
  const double grow = std::sqrt(2.0 * kPi / (kSides * std::sin(2.0 * kPi / kSides)));
  const dvec3 e1 = glm::normalize(glm::cross(cap.axis, std::fabs(cap.axis.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0)));
  const dvec3 e2 = glm::cross(cap.axis, e1);
  const double r = std::tan(cap.half_angle) * grow;
  LtcPolygon poly = start;
  auto corner = [&](int k) {
    const double phi = 2.0 * kPi * k / kSides;
    return glm::vec3(cap.axis + r * (std::cos(phi) * e1 + std::sin(phi) * e2));
  };
  glm::vec3 previous = corner(kSides - 1);
  for (int k = 0; k < kSides; ++k) {
    const glm::vec3 next = corner(k);
    ltc_add_edge(poly, previous, next);
    previous = next;
  }
  return ltc_finish(poly);
}

// The second stage: from the first stage's x, the transform whose integrals over the caps above
// match the lobe's (fractions of its albedo, by its sampler on a 128 x 128 grid) in least
// squares, which is the quantity the area lights use; the first stage's density fit leaves its
// errors in the tails, where most lights are.
std::vector<double> fit_cap_integrals(const Lobe& lobe, double norm, const glm::dmat3& frame, std::vector<double> x,
                                      LtcFit& fit) {
  const std::vector<Cap> caps = fit_caps(frame[2], lobe.alpha);
  std::vector<double> target(caps.size(), 0.0);
  constexpr int kSamples = 128;
  for (int i = 0; i < kSamples; ++i) {
    for (int j = 0; j < kSamples; ++j) {
      double pdf = 0.0;
      const dvec3 l = lobe.sample((i + 0.5) / kSamples, (j + 0.5) / kSamples, pdf);
      if (!(pdf > 0.0)) continue;
      const double w = lobe.value(l) / pdf / (norm * kSamples * kSamples);
      if (!(w > 0.0)) continue;
      for (size_t k = 0; k < caps.size(); ++k)
        if (in_cap(caps[k], l)) target[k] += w;
    }
  }
  const glm::vec3 n(0.0f, 0.0f, 1.0f), v(lobe.v);
  auto objective = [&](const std::vector<double>& y) {
    if (!(y[0] > 0.0) || !(y[1] > 0.0)) return HUGE_VAL;
    const LtcPolygon start = ltc_polygon(n, v, glm::vec4(table_entry(transform(frame, y))));
    double sum = 0.0;
    for (size_t k = 0; k < caps.size(); ++k) {
      const double d = ltc_cap_integral(start, caps[k]) - target[k];
      sum += d * d;
    }
    return sum / double(caps.size());
  };
  double step = 0.1 * std::min(x[0], x[1]);
  for (int restart = 0; restart < 2; ++restart) {
    const NelderMeadResult r = minimize_nelder_mead(objective, x, step, 1e-8, 800);
    x = r.x;
    fit.cap_error = r.value;
    fit.evaluations += r.evaluations;
    step = 0.05 * std::min(x[0], x[1]);
  }
  return x;
}

}  // namespace

double ltc_density(const glm::dmat3& m_inv, dvec3 l) {
  const dvec3 lo = m_inv * l;
  const double len = glm::length(lo);
  if (!(len > 0.0) || !(lo.z > 0.0)) return 0.0;
  return lo.z / len / kPi * std::fabs(glm::determinant(m_inv)) / (len * len * len);
}

LtcFit fit_ltc(double n_dot_v, double roughness) {
  n_dot_v = std::clamp(n_dot_v, 1e-4, 1.0);
  const Lobe lobe{dvec3(std::sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v), n_dot_v, ltc_alpha(roughness)};
  // The lobe's integral and mean direction, by its own sampler on the same grid.
  double norm = 0.0;
  dvec3 mean(0.0);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      double pdf = 0.0;
      const dvec3 l = lobe.sample(grid_u(i), grid_u(j), pdf);
      const double w = pdf > 0.0 ? lobe.value(l) / pdf : 0.0;
      norm += w;
      mean += w * l;
    }
  }
  norm /= kGrid * kGrid;
  mean.y = 0.0;  // zero by symmetry; the grid leaves rounding
  const dvec3 z = glm::length(mean) > 0.0 ? glm::normalize(mean) : dvec3(0.0, 0.0, 1.0);
  const glm::dmat3 frame(dvec3(z.z, 0.0, -z.x), dvec3(0.0, 1.0, 0.0), z);

  auto objective = [&](const std::vector<double>& x) {
    if (!(x[0] > 0.0) || !(x[1] > 0.0)) return HUGE_VAL;
    return fit_error(lobe, norm, transform(frame, x));
  };
  std::vector<double> x{lobe.alpha, lobe.alpha, 0.0, 0.0};
  LtcFit fit;
  double step = 0.5 * lobe.alpha;
  for (int restart = 0; restart < 3; ++restart) {
    const NelderMeadResult r = minimize_nelder_mead(objective, x, step, 1e-9, 1500);
    x = r.x;
    fit.error = r.value;
    fit.evaluations += r.evaluations;
    step = 0.1 * std::min(x[0], x[1]);
  }
  x = fit_cap_integrals(lobe, norm, frame, x, fit);
  fit.m = transform(frame, x);
  fit.entry = table_entry(fit.m);
  return fit;
}

}  // namespace lg
