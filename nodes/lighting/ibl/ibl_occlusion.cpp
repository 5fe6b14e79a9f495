#include "nodes/lighting/ibl/ibl_occlusion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "nodes/env/common/sh_basis.h"

namespace lg {

double cone_band4_ratio(double c) {
  const double c2 = c * c;
  return 1 + c2 * (10 - 35 * c2);
}

std::array<double, 9> cone_lobe_weights(const glm::dvec3& n, const glm::dvec3& b, double c) {
  constexpr double pi = std::numbers::pi;
  // The integrals over the cone about b of (n . w), w (n . w) and w w^T (n . w), over 1 - c^2:
  // about the axis w = z b + sqrt(1 - z^2) u, the odd powers of u average out (README).
  const double bn = glm::dot(b, n);
  const glm::dvec3 pn = n - bn * b;  // n's part across the axis
  const double cosine = pi * bn;
  const double along2 = 2 * pi * (1 + c + c * c) / (3 * (1 + c)), across2 = pi * (1 - c) * (2 + c) / (3 * (1 + c));
  const double along3 = pi * (1 + c * c) / 2, across3 = pi * (1 - c * c) / 4;
  const glm::dvec3 linear = along2 * bn * b + across2 * pn;
  double quadratic[3][3];  // symmetric
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double across = (i == j ? 1.0 : 0.0) - b[i] * b[j];
      quadratic[i][j] = along3 * bn * b[i] * b[j] + across3 * (b[i] * pn[j] + pn[i] * b[j] + bn * across);
    }
  // Bands 0 to 2 of the basis as polynomials (nodes/env/common/sh_basis.h: Y_1,-1 ~ y, Y_1,0 ~ z,
  // Y_1,1 ~ x), divided by the cosine lobe's band factors (the input is irradiance).
  const double k0 = 0.5 / std::sqrt(pi), k1 = std::sqrt(3 / (4 * pi)), k2 = std::sqrt(15 / (4 * pi));
  const double k20 = std::sqrt(5 / pi) / 4, k22 = std::sqrt(15 / pi) / 4;
  const double a0 = pi, a1 = 2 * pi / 3, a2 = pi / 4;
  return {k0 * cosine / a0,
          k1 * linear.y / a1,
          k1 * linear.z / a1,
          k1 * linear.x / a1,
          k2 * quadratic[0][1] / a2,
          k2 * quadratic[1][2] / a2,
          k20 * (3 * quadratic[2][2] - cosine) / a2,
          k2 * quadratic[0][2] / a2,
          k22 * (quadratic[0][0] - quadratic[1][1]) / a2};
}

glm::dvec3 cone_lobe_irradiance(std::span<const glm::dvec3> sh, const glm::dvec3& n, const glm::dvec3& bent,
                                double cone_cos, double visibility) {
  const std::array<double, 9> w = cone_lobe_weights(n, bent, cone_cos);
  glm::dvec3 e(0.0);
  for (size_t k = 0; k < std::min<size_t>(9, sh.size()); ++k) e += sh[k] * w[k];
  if (sh.size() > 16) {
    std::vector<double> y(sh_count(kMaxShOrder));
    sh_evaluate(kMaxShOrder, bent, y);
    for (size_t k = 16; k < sh.size(); ++k) e += sh[k] * (cone_band4_ratio(cone_cos) * y[k]);
  }
  return glm::max(e * visibility, glm::dvec3(0.0));
}

double specular_cone_cosine(double roughness) {
  const double a2 = std::pow(roughness, 4);
  return 2 * (1 - a2) / (2 - a2);
}

double cap_intersection(double cos1, double cos2, double cos_d) {
  const double r1 = std::acos(std::clamp(cos1, -1.0, 1.0)), r2 = std::acos(std::clamp(cos2, -1.0, 1.0));
  const double d = std::acos(std::clamp(cos_d, -1.0, 1.0));
  if (d >= r1 + r2) return 0;
  if (d <= std::abs(r1 - r2)) return 2 * std::numbers::pi * (1 - std::max(cos1, cos2));
  // One sine numerator for the three angles (see ibl_occlusion.glsl).
  const double g = std::sqrt(std::max(1 - cos1 * cos1 - cos2 * cos2 - cos_d * cos_d + 2 * cos1 * cos2 * cos_d, 0.0));
  const double lens = std::atan2(g, cos_d - cos1 * cos2);
  const double edge1 = std::atan2(g, cos2 - cos_d * cos1);
  const double edge2 = std::atan2(g, cos1 - cos_d * cos2);
  return std::max(2 * (std::numbers::pi - lens - cos1 * edge1 - cos2 * edge2), 0.0);
}

double specular_occlusion_from_cone(const glm::dvec3& n, const glm::dvec3& r, const glm::dvec3& bent, double cone_cos,
                                    double roughness) {
  const double lobe_cos = specular_cone_cosine(roughness);
  if (1 - lobe_cos < 1e-5) return glm::dot(bent, r) >= cone_cos ? 1 : 0;
  const double above =
      std::max(cap_intersection(0, lobe_cos, glm::dot(n, r)), 0.05 * 2 * std::numbers::pi * (1 - lobe_cos));
  return std::clamp(cap_intersection(cone_cos, lobe_cos, glm::dot(bent, r)) / above, 0.0, 1.0);
}

double multi_bounce_cubic(double x, double albedo) {
  const double a = 2.0404 * albedo - 0.3324, b = -4.7951 * albedo + 0.6417, c = 2.7552 * albedo + 0.6903;
  return ((a * x + b) * x + c) * x;
}

double multi_bounce_occlusion(double visibility, double albedo) {
  return std::clamp(multi_bounce_cubic(visibility, albedo), visibility, 1.0);
}

}  // namespace lg
