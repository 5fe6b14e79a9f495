#include "nodes/lighting/ibl/ibl_occlusion.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "nodes/env/common/sh_basis.h"

namespace lg {

double cone_lobe_band_ratio(int l, double c) {
  const double c2 = c * c;
  switch (l) {
    case 0:
      return 1;
    case 1:
      return (1 + c + c2) / (1 + c);
    case 2:
      return 1 + 3 * c2;
    case 4:
      return 1 + c2 * (10 - 35 * c2);
    default:
      return 0;
  }
}

glm::dvec3 cone_lobe_irradiance(std::span<const glm::dvec3> sh, const glm::dvec3& bent, double cone_cos,
                                double visibility) {
  const int order = int(std::lround(std::sqrt(double(sh.size())))) - 1;
  std::vector<double> y(sh.size());
  sh_evaluate(order, bent, y);
  glm::dvec3 e(0.0);
  for (int l = 0; l <= order; ++l) {
    const double ratio = cone_lobe_band_ratio(l, cone_cos);
    for (int k = l * l; k < (l + 1) * (l + 1); ++k) e += sh[k] * (ratio * y[k]);
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
  const double s1 = std::sin(r1), s2 = std::sin(r2), sd = std::sin(d);
  auto angle = [](double x) { return std::acos(std::clamp(x, -1.0, 1.0)); };
  const double lens = angle((cos_d - cos1 * cos2) / (s1 * s2));
  const double edge1 = angle((cos2 - cos_d * cos1) / (sd * s1));
  const double edge2 = angle((cos1 - cos_d * cos2) / (sd * s2));
  return std::max(2 * (std::numbers::pi - lens - cos1 * edge1 - cos2 * edge2), 0.0);
}

double specular_occlusion_from_cone(const glm::dvec3& n, const glm::dvec3& r, const glm::dvec3& bent, double cone_cos,
                                    double roughness) {
  const double lobe_cos = specular_cone_cosine(roughness);
  if (1 - lobe_cos < 1e-5) return glm::dot(bent, r) >= cone_cos ? 1 : 0;
  const double above = cap_intersection(0, lobe_cos, glm::dot(n, r));
  if (above <= 0) return 1;
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
