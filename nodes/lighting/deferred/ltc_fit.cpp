#include "nodes/lighting/deferred/ltc_fit.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numbers>
#include <vector>

#include "nodes/env/brdf_lut/dfg_reference.h"
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
  fit.m = transform(frame, x);
  const glm::dmat3 inv = glm::inverse(fit.m);
  const double s = inv[1][1];
  // (row, column) = [column][row] in glm.
  fit.entry = glm::dvec4(inv[0][0], inv[2][0], inv[0][2], inv[2][2]) / s;
  return fit;
}

}  // namespace lg
