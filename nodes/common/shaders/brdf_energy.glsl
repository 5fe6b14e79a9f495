// How the specular and diffuse lobes share energy, from the GGX lobe's split-sum scale A and
// bias B at the view (the DFG table in lighting.ibl, brdf_albedo.glsl's table for direct light;
// nodes/env/brdf_lut/brdf_albedo.h is the same in double precision).
#ifndef LG_BRDF_ENERGY_GLSL
#define LG_BRDF_ENERGY_GLSL

// E = A + B, the lobe's white albedo (Fresnel 1), floored where it divides.
float white_albedo(vec2 scale_bias) {
  return max(scale_bias.x + scale_bias.y, 1e-4);
}

// Multiple scattering returns what single scattering loses (1 - E, E = A + B the white albedo)
// in proportion to F0: the single-scattering specular times 1 + F0 (1 / E - 1) (Fdez-Aguera
// 2019). A white metal (F0 = 1) then reflects all of a constant environment.
vec3 specular_energy_scale(vec3 f0, vec2 scale_bias) {
  return 1.0 + f0 * (1.0 / white_albedo(scale_bias) - 1.0);
}

// The specular lobe's albedo with that compensation: what the diffuse lobe does not get. The
// diffuse is weighted by 1 minus this, so a white dielectric reflects a constant environment
// whole too.
vec3 specular_albedo(vec3 f0, vec2 scale_bias) {
  return (f0 * scale_bias.x + scale_bias.y) * specular_energy_scale(f0, scale_bias);
}

#endif
