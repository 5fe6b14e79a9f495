// The environment as lighting.ibl and scene.forward_transparent read it, at bindings 6 to 9:
// SH irradiance coefficients (env.sh_project with convolve_cosine) or an irradiance map holding
// E / pi (env.irradiance), the prefiltered specular map and the DFG table, with the shading of
// ibl_shading.glsl (nodes/lighting/ibl/ibl_reference.h is the same in double precision).
#ifndef LG_IBL_ENVIRONMENT_GLSL
#define LG_IBL_ENVIRONMENT_GLSL

#include "nodes/env/common/shaders/sh_basis.glsl"
#include "nodes/lighting/ibl/shaders/ibl_shading.glsl"

// The SH coefficients: a storage buffer, or where the includer defines LG_IBL_SH_UNIFORM_COUNT
// (lighting.ibl), the same buffer as a uniform block of that many. lavapipe (Mesa 22.3) loads
// from a storage buffer one pixel at a time even where every pixel reads the same element, and
// from a uniform block once for all.
#ifdef LG_IBL_SH_UNIFORM_COUNT
layout(std140, binding = 6) uniform Sh { vec4 sh[LG_IBL_SH_UNIFORM_COUNT]; };
#else
layout(std430, binding = 6) readonly buffer Sh { vec4 sh[]; };
#endif
layout(binding = 7) uniform samplerCube irradiance_map;
layout(binding = 8) uniform samplerCube specular_map;
layout(binding = 9) uniform sampler2D dfg_lut;

// Irradiance at unit normal n from the (cosine-convolved) SH coefficients.
vec3 sh_irradiance(vec3 n) {
  float y[LG_SH_MAX_COUNT];
  sh_evaluate(n, y);
  int count = min(int(sh.length()), LG_SH_MAX_COUNT);
  vec3 e = vec3(0.0);
  for (int k = 0; k < count; ++k) e += sh[k].rgb * y[k];
  return max(e, vec3(0.0));  // ringing must not light negatively
}

// The prefiltered map along the reflection r at mip roughness (mips - 1).
vec3 prefiltered_radiance(vec3 r, float roughness) {
  float mips = float(textureQueryLevels(specular_map));
  return textureLod(specular_map, r, roughness * (mips - 1.0)).rgb;
}

// The DFG table's scale A and bias B at (n.v, roughness).
vec2 dfg_scale_bias(float n_dot_v, float roughness) {
  return textureLod(dfg_lut, dfg_uv(n_dot_v, roughness, vec2(textureSize(dfg_lut, 0))), 0.0).rg;
}

// E / pi at unit normal n from the environment: its SH when `from_sh`, else its irradiance map.
vec3 environment_irradiance_over_pi(vec3 n, bool from_sh) {
  return from_sh ? sh_irradiance(n) / LG_SH_PI : textureLod(irradiance_map, n, 0.0).rgb;
}

// The diffuse image-based light leaving a surface: `irradiance_over_pi` (E / pi) reflected by
// what the specular lobe leaves at this view (`scale_bias`: the DFG table's), times `occlusion`
// (per channel: lighting.ibl's multi-bounce occlusion is coloured).
vec3 image_based_diffuse(vec3 diffuse_color, vec3 f0, vec2 scale_bias, vec3 irradiance_over_pi, vec3 occlusion) {
  return diffuse_color * (1.0 - specular_albedo(f0, scale_bias)) * irradiance_over_pi * occlusion;
}

// The environment's specular light leaving a surface toward v through the split sum, darkened by
// the material's own occlusion (1: none) by Lagarde's form, as lighting.ibl does.
vec3 environment_specular(vec3 n, vec3 v, vec3 f0, float roughness, float occlusion, vec2 scale_bias) {
  float n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
  vec3 specular = split_sum_specular(prefiltered_radiance(reflect(-v, n), roughness), f0, scale_bias);
  if (occlusion < 1.0) specular *= specular_occlusion_from_ao(n_dot_v, occlusion, roughness);
  return specular;
}

#endif
