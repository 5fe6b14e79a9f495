// The real SH basis on the CPU: hand-written bands 0 to 2 (fixing ordering and sign),
// orthonormality up to band 4 by exact quadrature, the cosine-lobe factors, and the windows.
#include "nodes/env/common/sh_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <vector>

namespace lg::test {
namespace {

constexpr double pi = std::numbers::pi;

TEST(ShBasis, BandsZeroToTwoMatchTheClosedForms) {
  std::mt19937_64 rng(21);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 100; ++k) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const double x = d.x, y = d.y, z = d.z;
    const double c1 = std::sqrt(3 / (4 * pi)), c2 = std::sqrt(15 / (4 * pi)), c20 = std::sqrt(5 / (16 * pi));
    const double expected[9] = {
        1 / (2 * std::sqrt(pi)), c1 * y, c1 * z, c1 * x, c2 * x * y, c2 * y * z, c20 * (3 * z * z - 1), c2 * x * z,
        c2 / 2 * (x * x - y * y)};
    double y_lm[9];
    sh_evaluate(2, d, y_lm);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(y_lm[i], expected[i], 1e-14) << i;
  }
}

// Gauss-Legendre in cos(theta) (exact for the degree-8 products of band-4 functions) and an
// even grid in phi.
TEST(ShBasis, IsOrthonormalUpToBandFour) {
  const int order = 4, count = sh_count(order);
  // 16-point Gauss-Legendre nodes by Newton's method on P_16.
  const int n = 16;
  std::vector<double> nodes(n), weights(n);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(pi * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = t;
      for (int l = 2; l <= n; ++l) {
        const double p2 = ((2 * l - 1) * t * p1 - (l - 1) * p0) / l;
        p0 = p1, p1 = p2;
      }
      const double dp = n * (t * p1 - p0) / (t * t - 1);
      t -= p1 / dp;
      weights[i] = 2 / ((1 - t * t) * dp * dp);
    }
    nodes[i] = t;
  }
  std::vector<double> gram(count * count, 0.0), y(count);
  const int phis = 32;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < phis; ++k) {
      const double phi = 2 * pi * k / phis, s = std::sqrt(1 - nodes[i] * nodes[i]);
      sh_evaluate(order, {s * std::cos(phi), s * std::sin(phi), nodes[i]}, y);
      for (int a = 0; a < count; ++a)
        for (int b = 0; b < count; ++b) gram[a * count + b] += weights[i] * 2 * pi / phis * y[a] * y[b];
    }
  for (int a = 0; a < count; ++a)
    for (int b = 0; b < count; ++b) EXPECT_NEAR(gram[a * count + b], a == b ? 1.0 : 0.0, 1e-12) << a << " " << b;
}

TEST(ShBasis, CosineLobeFactorsMatchIntegration) {
  // A_l = 2 pi * integral over [0, 1] of t P_l(t) dt, by a fine midpoint rule.
  for (int l = 0; l <= kMaxShOrder; ++l) {
    double sum = 0;
    const int steps = 200000;
    for (int k = 0; k < steps; ++k) {
      const double t = (k + 0.5) / steps;
      std::vector<double> band(l + 1, 0.0);
      band[l] = 4 * pi / (2 * l + 1);  // sh_impulse_response then gives P_l(t)
      sum += t * sh_impulse_response(band, t) / steps;
    }
    EXPECT_NEAR(cosine_lobe_band(l), 2 * pi * sum, 1e-9) << l;
  }
  EXPECT_NEAR(cosine_lobe_band(4), -pi / 24, 1e-15);
}

TEST(ShWindows, StartAtOneAndFallWithTheBand) {
  for (ShWindow w : {ShWindow::hanning, ShWindow::lanczos, ShWindow::min_ringing})
    for (int order = 1; order <= 4; ++order) {
      const std::vector<double> f = sh_window(w, order, 0.01, false);
      ASSERT_EQ(f.size(), size_t(order + 1));
      EXPECT_EQ(f[0], 1.0);
      for (int l = 1; l <= order; ++l) {
        EXPECT_LT(f[l], f[l - 1]) << order << " " << l;
        EXPECT_GT(f[l], 0.0);
      }
    }
  EXPECT_EQ(sh_window(ShWindow::none, 3, 0.1, false), std::vector<double>(4, 1.0));
}

double negative_lobe(const std::vector<double>& window, bool convolved) {
  std::vector<double> f(window);
  for (size_t l = 0; l < f.size(); ++l) f[l] *= convolved ? cosine_lobe_band(int(l)) : 1.0;
  double lowest = 0;
  for (int k = 0; k <= 4096; ++k) lowest = std::min(lowest, sh_impulse_response(f, std::cos(pi * k / 4096)));
  return -lowest / sh_impulse_response(f, 1.0);
}

TEST(ShWindows, MinimumRingingMeetsItsTargetWithTheLeastSmoothing) {
  for (bool convolved : {false, true})
    for (int order = 2; order <= 4; ++order)
      for (double target : {0.0, 0.01, 0.05}) {
        const std::vector<double> w = sh_window(ShWindow::min_ringing, order, target, convolved);
        EXPECT_LE(negative_lobe(w, convolved), target + 1e-6) << order << " " << target;
        // A little less smoothing (lambda 2% smaller) breaks the target, unless none was needed.
        const double lambda = (1 / w[1] - 1) / 4;
        if (lambda == 0) continue;
        std::vector<double> weaker(w.size());
        for (size_t l = 0; l < w.size(); ++l) weaker[l] = 1 / (1 + 0.98 * lambda * l * l * (l + 1.0) * (l + 1.0));
        EXPECT_GT(negative_lobe(weaker, convolved), target) << order << " " << target;
      }
}

}  // namespace
}  // namespace lg::test
