#include "nodes/gi/path_tracer/microfacet_brdf.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "nodes/env/brdf_lut/brdf_albedo.h"
#include "nodes/raytrace/cosine_sampling.h"

namespace lg {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMinAlpha = 1e-3;  // brdf.glsl's LG_MIN_ALPHA
constexpr double kMinNDotV = 1e-4;  // brdf.glsl clamps n.v so

double ggx_distribution(double n_dot_h, double alpha) {
  const double a2 = alpha * alpha;
  const double d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

// G2 / (4 n.l n.v), height-correlated (Heitz 2014).
double smith_visibility(double n_dot_v, double n_dot_l, double alpha) {
  const double a2 = alpha * alpha;
  const double gv = n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);
  const double gl = n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);
  return 0.5 / std::max(gv + gl, 1e-7);
}

double smith_g1(double n_dot_v, double alpha) {
  const double a2 = alpha * alpha;
  return 2.0 * n_dot_v / (n_dot_v + std::sqrt(a2 + (1.0 - a2) * n_dot_v * n_dot_v));
}

glm::dvec3 fresnel_schlick(glm::dvec3 f0, double v_dot_h) {
  const double f = std::pow(1.0 - std::clamp(v_dot_h, 0.0, 1.0), 5.0);
  return f0 + (1.0 - f0) * f;
}

double luminance(glm::dvec3 c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The view the specular sampler works with: v lifted to n.v >= kMinNDotV, as brdf.glsl's clamp
// treats a view below the shading normal (interpolated normals allow it).
glm::dvec3 sampling_view(const BrdfSurface& s, glm::dvec3 v) {
  const double n_dot_v = glm::dot(s.normal, v);
  if (n_dot_v >= kMinNDotV) return v;
  const glm::dvec3 tangential = v - n_dot_v * s.normal;
  const double t = glm::length(tangential);
  if (!(t > 1e-12)) return s.normal;
  return glm::normalize(tangential / t * std::sqrt(1.0 - kMinNDotV * kMinNDotV) + kMinNDotV * s.normal);
}

}  // namespace

BrdfSurface make_brdf_surface(glm::dvec3 normal, const SurfaceMaterial& m) {
  BrdfSurface s;
  s.normal = normal;
  s.diffuse_color = m.base_color * (1.0 - m.metalness);
  s.f0 = glm::mix(glm::dvec3(0.04), m.base_color, m.metalness);
  s.roughness = m.roughness;
  s.alpha = std::max(m.roughness * m.roughness, kMinAlpha);
  return s;
}

BrdfCosine evaluate_brdf(const BrdfSurface& s, glm::dvec3 v, glm::dvec3 l) {
  BrdfCosine out;
  const double n_dot_l = glm::dot(s.normal, l);
  if (!(n_dot_l > 0.0)) return out;
  const double n_dot_v = std::max(glm::dot(s.normal, v), kMinNDotV);
  const glm::dvec2 scale_bias = brdf_albedo_lookup(n_dot_v, s.roughness);
  out.diffuse = s.diffuse_color * (1.0 - specular_albedo(s.f0, scale_bias)) / kPi * n_dot_l;
  const glm::dvec3 h = glm::normalize(l + v);
  const double n_dot_h = std::clamp(glm::dot(s.normal, h), 0.0, 1.0);
  out.specular = ggx_distribution(n_dot_h, s.alpha) * smith_visibility(n_dot_v, n_dot_l, s.alpha) *
                 fresnel_schlick(s.f0, glm::dot(v, h)) * specular_energy_scale(s.f0, scale_bias) * n_dot_l;
  return out;
}

glm::dvec3 diffuse_reflectance(const BrdfSurface& s, glm::dvec3 v) {
  const double n_dot_v = std::max(glm::dot(s.normal, v), kMinNDotV);
  return s.diffuse_color * (1.0 - specular_albedo(s.f0, brdf_albedo_lookup(n_dot_v, s.roughness)));
}

double specular_lobe_probability(const BrdfSurface& s, glm::dvec3 v) {
  const double specular = luminance(fresnel_schlick(s.f0, std::max(glm::dot(s.normal, v), 0.0)));
  const double diffuse = luminance(s.diffuse_color);
  if (!(diffuse > 0.0)) return 1.0;
  // Never starve a lobe completely: a dark-looking lobe can still carry a bright light.
  return std::clamp(specular / (specular + diffuse), 0.05, 0.95);
}

glm::dvec3 sample_diffuse(const BrdfSurface& s, glm::dvec2 u) {
  return make_frame(s.normal).to_world(cosine_hemisphere(u));
}

glm::dvec3 sample_specular(const BrdfSurface& s, glm::dvec3 v, glm::dvec2 u) {
  const Frame frame = make_frame(s.normal);
  const glm::dvec3 view = sampling_view(s, v);
  const glm::dvec3 v_local(glm::dot(view, frame.tangent), glm::dot(view, frame.bitangent),
                           glm::dot(view, frame.normal));
  // The view in the hemisphere configuration where the distribution is a unit half sphere.
  const glm::dvec3 vh = glm::normalize(glm::dvec3(s.alpha * v_local.x, s.alpha * v_local.y, v_local.z));
  const double length2 = vh.x * vh.x + vh.y * vh.y;
  const glm::dvec3 t1 = length2 > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(length2) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 t2 = glm::cross(vh, t1);
  const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
  const double p1 = r * std::cos(phi);
  const double blend = 0.5 * (1.0 + vh.z);
  const double p2 = (1.0 - blend) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + blend * r * std::sin(phi);
  const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  const glm::dvec3 h_local = glm::normalize(glm::dvec3(s.alpha * nh.x, s.alpha * nh.y, std::max(0.0, nh.z)));
  const glm::dvec3 h = frame.to_world(h_local);
  return 2.0 * glm::dot(view, h) * h - view;
}

double diffuse_pdf(const BrdfSurface& s, glm::dvec3 l) {
  return std::max(glm::dot(s.normal, l), 0.0) / kPi;
}

double specular_pdf(const BrdfSurface& s, glm::dvec3 v, glm::dvec3 l) {
  const glm::dvec3 view = sampling_view(s, v);
  const glm::dvec3 sum = l + view;
  const double length = glm::length(sum);
  if (!(length > 1e-12)) return 0.0;
  const glm::dvec3 h = sum / length;
  const double n_dot_h = glm::dot(s.normal, h), v_dot_h = glm::dot(view, h);
  if (!(n_dot_h > 0.0) || !(v_dot_h > 0.0)) return 0.0;
  const double n_dot_v = glm::dot(s.normal, view);
  // D_v(h) / (4 v.h) with D_v(h) = G1(v) (v.h) D(h) / (n.v).
  return smith_g1(n_dot_v, s.alpha) * ggx_distribution(n_dot_h, s.alpha) / (4.0 * n_dot_v);
}

}  // namespace lg
