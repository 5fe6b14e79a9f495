// lighting.ibl's shading of one surface in double precision (the formulas of
// nodes/lighting/ibl/shaders/ibl_shading.glsl and ibl.comp, for tests): given the irradiance E
// at the normal, the prefiltered radiance along the reflection and the DFG table's (A, B).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace lg {

struct IblSurface {
  glm::dvec3 albedo{1.0};
  double roughness = 0.5, metalness = 0;
};

// Lagarde and de Rousiers' specular occlusion from ambient occlusion.
double specular_occlusion_from_ao(double n_dot_v, double ao, double roughness);

// Diffuse (weighted by 1 minus the specular albedo) plus specular, before ambient and specular
// occlusion.
glm::dvec3 ibl_shade_reference(const IblSurface& surface, const glm::dvec3& irradiance, const glm::dvec3& prefiltered,
                               const glm::dvec2& scale_bias);

}  // namespace lg
