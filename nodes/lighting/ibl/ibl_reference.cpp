#include "nodes/lighting/ibl/ibl_reference.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nodes/env/brdf_lut/brdf_albedo.h"

namespace lg {

double specular_occlusion_from_ao(double n_dot_v, double ao, double roughness) {
  return std::clamp(std::pow(n_dot_v + ao, std::exp2(-16 * roughness - 1)) - 1 + ao, 0.0, 1.0);
}

glm::dvec3 ibl_shade_reference(const IblSurface& s, const glm::dvec3& irradiance, const glm::dvec3& prefiltered,
                               const glm::dvec2& scale_bias) {
  const glm::dvec3 diffuse_color = s.albedo * (1 - s.metalness);
  const glm::dvec3 f0 = glm::dvec3(0.04) * (1 - s.metalness) + s.albedo * s.metalness;
  const glm::dvec3 specular = specular_albedo(f0, scale_bias);
  return diffuse_color * (1.0 - specular) / std::numbers::pi * irradiance + prefiltered * specular;
}

}  // namespace lg
