#include "nodes/env/sky/sky_model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lg {
namespace {

// theta: the direction's zenith angle (cos given), gamma: its angle to the sun.
double perez(const std::array<double, 5>& c, double cos_theta, double gamma) {
  const double cos_gamma = std::cos(gamma);
  return (1 + c[0] * std::exp(c[1] / std::max(cos_theta, 0.01))) *
         (1 + c[2] * std::exp(c[3] * gamma) + c[4] * cos_gamma * cos_gamma);
}

glm::dvec3 xyy_to_rec709(double x, double y, double luminance) {
  const double X = x / y * luminance, Z = (1 - x - y) / y * luminance;
  return glm::max(glm::dvec3(3.2404542 * X - 1.5371385 * luminance - 0.4985314 * Z,
                             -0.9692660 * X + 1.8760108 * luminance + 0.0415560 * Z,
                             0.0556434 * X - 0.2040259 * luminance + 1.0572252 * Z),
                  glm::dvec3(0.0));
}

}  // namespace

SkyModel make_sky_model(const SkyParams& p) {
  SkyModel m{};
  const double length = glm::length(p.sun_direction);
  m.sun = length > 1e-12 ? p.sun_direction / length : glm::dvec3(0, 1, 0);
  const double across = std::hypot(m.sun.x, m.sun.z);
  m.sky_sun = m.sun.y >= 0 ? m.sun
              : across > 0 ? glm::dvec3(m.sun.x / across, 0, m.sun.z / across)
                           : glm::dvec3(1, 0, 0);
  m.sun_radiance = p.sun_intensity;
  const double t = p.turbidity;
  m.perez = {
      {{0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703},
       {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452},
       {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529}}};
  // A sun below the horizon lights the sky as at sunset (the model has no night).
  const double theta_s = std::acos(std::clamp(m.sky_sun.y, 0.0, 1.0));
  const double t2 = t * t, s = theta_s, s2 = s * s, s3 = s2 * s;
  const double x_zenith = t2 * (0.00166 * s3 - 0.00375 * s2 + 0.00209 * s) +
                          t * (-0.02903 * s3 + 0.06377 * s2 - 0.03202 * s + 0.00394) +
                          (0.11693 * s3 - 0.21196 * s2 + 0.06052 * s + 0.25886);
  const double y_zenith = t2 * (0.00275 * s3 - 0.00610 * s2 + 0.00317 * s) +
                          t * (-0.04214 * s3 + 0.08970 * s2 - 0.04153 * s + 0.00516) +
                          (0.15346 * s3 - 0.26756 * s2 + 0.06670 * s + 0.26688);
  const double zenith[3] = {1.0, x_zenith, y_zenith};
  for (int c = 0; c < 3; ++c) m.zenith_scale[c] = zenith[c] / perez(m.perez[c], 1.0, theta_s);
  // The ground's irradiance: the sky over the upper hemisphere (midpoint rule in theta, phi)
  // and the sun; a Lambertian ground reflects albedo E / pi.
  glm::dvec3 irradiance = m.sun_radiance * sun_solid_angle() * std::max(m.sun.y, 0.0) * glm::dvec3(1.0);
  const int n_theta = 256, n_phi = 512;
  const double d_theta = std::numbers::pi / 2 / n_theta, d_phi = 2 * std::numbers::pi / n_phi;
  for (int a = 0; a < n_theta; ++a)
    for (int b = 0; b < n_phi; ++b) {
      const double theta = (a + 0.5) * d_theta, phi = (b + 0.5) * d_phi;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      irradiance += sky_radiance(m, d) * std::cos(theta) * std::sin(theta) * d_theta * d_phi;
    }
  m.ground = kGroundAlbedo / std::numbers::pi * irradiance;
  return m;
}

glm::dvec3 sky_radiance(const SkyModel& m, const glm::dvec3& direction) {
  const glm::dvec3 d = glm::normalize(direction);
  if (d.y < 0) return m.ground;
  const double gamma = std::acos(std::clamp(glm::dot(d, m.sky_sun), -1.0, 1.0));
  double v[3];
  for (int c = 0; c < 3; ++c) v[c] = m.zenith_scale[c] * perez(m.perez[c], d.y, gamma);
  return xyy_to_rec709(v[1], v[2], v[0]);
}

double sun_solid_angle() {
  return 2 * std::numbers::pi * (1 - std::cos(kSunAngularRadius));
}

CubeImage render_sky_reference(const SkyModel& model, uint32_t size, uint32_t subdivide, int sun_points) {
  CubeImage cube(size);
  const uint32_t fine = size * subdivide;
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < size; ++j)
      for (uint32_t i = 0; i < size; ++i) {
        glm::dvec3 sum(0.0);
        for (uint32_t b = 0; b < subdivide; ++b)
          for (uint32_t a = 0; a < subdivide; ++a)
            for (const TexelSample& s : texel_quadrature(f, fine, i * subdivide + a, j * subdivide + b))
              sum += s.weight * sky_radiance(model, s.direction);
        cube.at(f, i, j) = glm::dvec4(sum / texel_solid_angle(size, i, j), 1.0);
      }
  const glm::dvec3 axis = model.sun;
  const glm::dvec3 t =
      glm::normalize(glm::cross(std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0), axis));
  const glm::dvec3 b = glm::cross(axis, t);
  const double energy = model.sun_radiance * sun_solid_angle() / sun_points;
  for (int k = 0; k < sun_points; ++k) {
    const double r = kSunAngularRadius * std::sqrt((k + 0.5) / sun_points), phi = 2.399963229728653 * k;
    const glm::dvec3 p = std::cos(r) * axis + std::sin(r) * (std::cos(phi) * t + std::sin(phi) * b);
    if (p.y < 0) continue;
    const CubeCoord c = cube_coord(p);
    const uint32_t i = std::min(size - 1, uint32_t(c.u * size)), j = std::min(size - 1, uint32_t(c.v * size));
    cube.at(c.face, i, j) += glm::dvec4(glm::dvec3(energy / texel_solid_angle(size, i, j)), 0.0);
  }
  return cube;
}

}  // namespace lg
