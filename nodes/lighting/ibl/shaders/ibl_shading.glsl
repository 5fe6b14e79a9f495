// lighting.ibl's shading of one surface (nodes/lighting/ibl/ibl_reference.h is the same in
// double precision): diffuse from irradiance, specular from the split sum with the DFG table's
// scale A and bias B and multiple-scattering energy compensation, the diffuse weighted by what
// the specular leaves (brdf_energy.glsl).
#ifndef LG_IBL_SHADING_GLSL
#define LG_IBL_SHADING_GLSL

#include "nodes/common/shaders/brdf_energy.glsl"

// Where the DFG table holds (n.v, roughness): texel centres run from 0 to 1 inclusive
// (nodes/env/brdf_lut/shaders/dfg.comp).
vec2 dfg_uv(float n_dot_v, float roughness, vec2 size) {
  return (vec2(n_dot_v, roughness) * (size - 1.0) + 0.5) / size;
}

// The split sum F0 A + B is the single-scattering reflectance, with multiple scattering's
// share on top (specular_albedo).
vec3 split_sum_specular(vec3 prefiltered, vec3 f0, vec2 scale_bias) {
  return prefiltered * specular_albedo(f0, scale_bias);
}

// Lagarde and de Rousiers' specular occlusion from ambient occlusion.
float specular_occlusion_from_ao(float n_dot_v, float ao, float roughness) {
  return clamp(pow(n_dot_v + ao, exp2(-16.0 * roughness - 1.0)) - 1.0 + ao, 0.0, 1.0);
}

#endif
