// Reads the surface at a texel of the G-buffer for the deferred passes, its lobes sharing energy
// by the albedo table in the constants (brdf_albedo.glsl).
#ifndef LG_DEFERRED_SURFACE_GLSL
#define LG_DEFERRED_SURFACE_GLSL

#include "nodes/common/shaders/brdf.glsl"
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"
#include "nodes/lighting/deferred/shaders/lights.glsl"

// Surfaces the G-buffer holds: depth > 0 (0 is the far plane, where no surface was drawn).
layout(binding = 1) uniform sampler2D gbuffer_depth;
layout(binding = 2) uniform sampler2D gbuffer_normal;
layout(binding = 3) uniform sampler2D gbuffer_albedo;
layout(binding = 4) uniform sampler2D gbuffer_material;

// False where no surface was drawn (the far plane) or the depth is not a finite number.
bool read_surface(ivec2 texel, out Surface s) {
  float depth = texelFetch(gbuffer_depth, texel, 0).r;
  if (!(depth > 0.0 && depth <= 1.0)) return false;
  vec3 p = world_position(camera, texel, depth);
  vec3 n = decode_normal(texelFetch(gbuffer_normal, texel, 0).rgb);
  vec3 albedo = texelFetch(gbuffer_albedo, texel, 0).rgb;
  vec2 material = texelFetch(gbuffer_material, texel, 0).rg;
  s = make_surface(p, n, camera.position.xyz, albedo, material.r, material.g);
  share_energy(s, brdf_albedo_lookup(max(dot(s.normal, s.view), 1e-4), material.r));
  return true;
}

#endif
