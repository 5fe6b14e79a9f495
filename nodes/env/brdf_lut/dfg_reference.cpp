#include "nodes/env/brdf_lut/dfg_reference.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace lg {
namespace {

constexpr double pi = std::numbers::pi;

double smith_visibility(double n_dot_v, double n_dot_l, double alpha) {
  const double a2 = alpha * alpha;
  const double gv = n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1 - a2) + a2);
  const double gl = n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1 - a2) + a2);
  return 0.5 / (gv + gl);
}

double ggx(double n_dot_h, double alpha) {
  const double a2 = alpha * alpha, d = n_dot_h * n_dot_h * (a2 - 1) + 1;
  return a2 / (pi * d * d);
}

glm::dvec3 view(double n_dot_v) {
  return {std::sqrt(1 - n_dot_v * n_dot_v), 0, n_dot_v};
}

}  // namespace

double ggx_specular_brdf(double n_dot_v, double n_dot_l, double n_dot_h, double alpha) {
  return ggx(n_dot_h, alpha) * smith_visibility(n_dot_v, n_dot_l, alpha);
}

glm::dvec2 dfg_reference(double n_dot_v, double roughness, int steps) {
  const double alpha = roughness * roughness, a2 = alpha * alpha;
  const glm::dvec3 v = view(n_dot_v);
  const double lambda_v = 0.5 * (std::sqrt(a2 + (1 - a2) * n_dot_v * n_dot_v) / n_dot_v - 1);
  const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
  const double len2 = vh.x * vh.x + vh.y * vh.y;
  const glm::dvec3 t1 = len2 > 0 ? glm::dvec3(-vh.y, vh.x, 0) / std::sqrt(len2) : glm::dvec3(1, 0, 0);
  const glm::dvec3 t2 = glm::cross(vh, t1);
  const double s = 0.5 * (1 + vh.z);
  glm::dvec2 sum(0.0);
  const int phis = 4 * steps;
  for (int a = 0; a < steps; ++a) {
    const double r = std::sqrt((a + 0.5) / steps);
    for (int b = 0; b < phis; ++b) {
      const double phi = 2 * pi * (b + 0.5) / phis;
      const double p1 = r * std::cos(phi);
      const double p2 = (1 - s) * std::sqrt(std::max(1 - p1 * p1, 0.0)) + s * r * std::sin(phi);
      const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(1 - p1 * p1 - p2 * p2, 0.0)) * vh;
      const glm::dvec3 h = glm::normalize(glm::dvec3(alpha * nh.x, alpha * nh.y, std::max(nh.z, 0.0)));
      const double v_dot_h = glm::dot(v, h);
      const glm::dvec3 l = 2 * v_dot_h * h - v;
      if (l.z <= 0 || v_dot_h <= 0) continue;
      const double weight = 4 * l.z * n_dot_v * smith_visibility(n_dot_v, l.z, alpha) * (1 + lambda_v);
      const double fc = std::pow(1 - v_dot_h, 5);
      sum += weight * glm::dvec2(1 - fc, fc);
    }
  }
  return sum / double(steps * phis);
}

glm::dvec2 dfg_reference_over_light(double n_dot_v, double roughness, int steps) {
  const double alpha = roughness * roughness;
  const glm::dvec3 v = view(n_dot_v);
  glm::dvec2 sum(0.0);
  const double d_theta = pi / 2 / steps, d_phi = 2 * pi / (2 * steps);
  for (int a = 0; a < steps; ++a) {
    const double theta = (a + 0.5) * d_theta;
    for (int b = 0; b < 2 * steps; ++b) {
      const double phi = (b + 0.5) * d_phi;
      const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const glm::dvec3 h = glm::normalize(l + v);
      const double v_dot_h = glm::dot(v, h);
      const double f = ggx(h.z, alpha) * smith_visibility(n_dot_v, l.z, alpha) * l.z;
      const double fc = std::pow(1 - v_dot_h, 5);
      sum += f * std::sin(theta) * d_theta * d_phi * glm::dvec2(1 - fc, fc);
    }
  }
  return sum;
}

}  // namespace lg
