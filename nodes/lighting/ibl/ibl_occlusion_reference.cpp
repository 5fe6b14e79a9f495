#include "nodes/lighting/ibl/ibl_occlusion_reference.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {

namespace {

// Two unit vectors completing `axis` to a right-handed frame.
void tangent_frame(const glm::dvec3& axis, glm::dvec3& t, glm::dvec3& b) {
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  t = glm::normalize(glm::cross(helper, axis));
  b = glm::cross(axis, t);
}

}  // namespace

glm::dvec3 cone_irradiance_quadrature(const std::function<glm::dvec3(const glm::dvec3&)>& radiance, const glm::dvec3& n,
                                      const glm::dvec3& axis, double cone_cos, int steps) {
  glm::dvec3 t, b;
  tangent_frame(axis, t, b);
  const int rings = steps, around = 2 * steps;
  const double dz = (1 - cone_cos) / rings, dphi = 2 * std::numbers::pi / around;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < rings; ++i) {
    const double z = cone_cos + (i + 0.5) * dz, s = std::sqrt(std::max(1 - z * z, 0.0));
    for (int j = 0; j < around; ++j) {
      const double phi = (j + 0.5) * dphi;
      const glm::dvec3 w = z * axis + s * (std::cos(phi) * t + std::sin(phi) * b);
      const double cosine = glm::dot(n, w);
      if (cosine > 0) sum += radiance(w) * cosine;
    }
  }
  return sum * (dz * dphi);
}

double cone_intersection_quadrature(const glm::dvec3& axis1, double cos1, const glm::dvec3& axis2, double cos2,
                                    int steps) {
  const double cos_d = std::clamp(glm::dot(axis1, axis2), -1.0, 1.0), sin_d = std::sqrt(1 - cos_d * cos_d);
  const double dz = (1 - cos2) / steps;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    // The ring at cosine z about axis2: w . axis1 = z cos_d + sqrt(1 - z^2) sin_d cos(phi).
    const double z = cos2 + (i + 0.5) * dz, s = std::sqrt(std::max(1 - z * z, 0.0));
    const double spread = s * sin_d;
    if (spread < 1e-15) {
      sum += z * cos_d >= cos1 ? 2 * std::numbers::pi : 0.0;
      continue;
    }
    sum += 2 * std::acos(std::clamp((cos1 - z * cos_d) / spread, -1.0, 1.0));
  }
  return sum * dz;
}

}  // namespace lg
