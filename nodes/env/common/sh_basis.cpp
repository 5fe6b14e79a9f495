#include "nodes/env/common/sh_basis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace lg {

void sh_evaluate(int order, const glm::dvec3& d, std::span<double> out) {
  // P_l^m(z) / sin^m(theta) by the usual recurrences, times Re/Im of (x + iy)^m = sin^m e^{im phi}:
  // polynomials in x, y, z with no division by sin(theta).
  double re = 1, im = 0;  // (x + iy)^m
  double pmm = 1;         // (2m - 1)!!
  for (int m = 0; m <= order; ++m) {
    double p_prev = 0, p = pmm;
    for (int l = m; l <= order; ++l) {
      if (l == m + 1)
        p_prev = p, p = d.z * (2 * m + 1) * pmm;
      else if (l > m + 1) {
        const double next = ((2 * l - 1) * d.z * p - (l + m - 1) * p_prev) / (l - m);
        p_prev = p, p = next;
      }
      double ratio = 1;  // (l - m)! / (l + m)!
      for (int k = l - m + 1; k <= l + m; ++k) ratio /= k;
      const double k_lm = std::sqrt((2 * l + 1) / (4 * std::numbers::pi) * ratio);
      if (m == 0)
        out[l * (l + 1)] = k_lm * p;
      else {
        out[l * (l + 1) + m] = std::numbers::sqrt2 * k_lm * p * re;
        out[l * (l + 1) - m] = std::numbers::sqrt2 * k_lm * p * im;
      }
    }
    const double re_next = re * d.x - im * d.y;
    im = re * d.y + im * d.x, re = re_next;
    pmm *= 2 * m + 1;
  }
}

double cosine_lobe_band(int l) {
  constexpr double pi = std::numbers::pi;
  if (l == 0) return pi;
  if (l == 1) return 2 * pi / 3;
  if (l % 2) return 0;
  // 2 pi (-1)^(l/2 - 1) / ((l + 2)(l - 1)) * l! / (2^l ((l/2)!)^2)
  double binomial = 1;  // l! / ((l/2)!)^2 / 2^l
  for (int k = 1; k <= l / 2; ++k) binomial *= double(l / 2 + k) / k / 4;
  const double sign = (l / 2 - 1) % 2 ? -1 : 1;
  return 2 * pi * sign / ((l + 2) * (l - 1)) * binomial;
}

ShWindow sh_window_from_name(std::string_view name) {
  if (name == "none") return ShWindow::none;
  if (name == "hanning") return ShWindow::hanning;
  if (name == "lanczos") return ShWindow::lanczos;
  if (name == "min_ringing") return ShWindow::min_ringing;
  throw std::invalid_argument("unknown SH window '" + std::string(name) + "'");
}

double sh_impulse_response(std::span<const double> band_factors, double cos_theta) {
  double sum = 0, p_prev = 0, p = 1;  // Legendre P_{l-1} and P_l by Bonnet's recurrence
  for (size_t l = 0; l < band_factors.size(); ++l) {
    sum += band_factors[l] * (2.0 * l + 1) / (4 * std::numbers::pi) * p;
    const double next = ((2.0 * l + 1) * cos_theta * p - double(l) * p_prev) / (l + 1.0);
    p_prev = p, p = next;
  }
  return sum;
}

namespace {

std::vector<double> min_ringing_window(int order, double lambda) {
  std::vector<double> w(order + 1);
  for (int l = 0; l <= order; ++l) w[l] = 1 / (1 + lambda * l * l * (l + 1.0) * (l + 1.0));
  return w;
}

// The deepest negative value of the impulse response relative to its peak (at theta = 0).
double negative_lobe(const std::vector<double>& window, int order, bool convolved) {
  std::vector<double> f(order + 1);
  for (int l = 0; l <= order; ++l) f[l] = window[l] * (convolved ? cosine_lobe_band(l) : 1.0);
  const double peak = sh_impulse_response(f, 1.0);
  double lowest = 0;
  constexpr int kSteps = 2048;
  for (int k = 0; k <= kSteps; ++k)
    lowest = std::min(lowest, sh_impulse_response(f, std::cos(std::numbers::pi * k / kSteps)));
  return -lowest / peak;
}

}  // namespace

std::vector<double> sh_window(ShWindow window, int order, double target, bool convolved) {
  std::vector<double> w(order + 1, 1.0);
  const double width = order + 1;
  for (int l = 1; l <= order; ++l) {
    const double x = std::numbers::pi * l / width;
    if (window == ShWindow::hanning) w[l] = 0.5 * (1 + std::cos(x));
    if (window == ShWindow::lanczos) w[l] = std::sin(x) / x;
  }
  if (window != ShWindow::min_ringing || negative_lobe(w, order, convolved) <= target) return w;
  // The negative lobe shrinks as lambda grows (the window tends to band 0 alone): bisect.
  double lo = 0, hi = 1;
  while (negative_lobe(min_ringing_window(order, hi), order, convolved) > target && hi < 1e12) hi *= 4;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (negative_lobe(min_ringing_window(order, mid), order, convolved) > target ? lo : hi) = mid;
  }
  return min_ringing_window(order, hi);
}

}  // namespace lg
