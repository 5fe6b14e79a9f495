#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's injection, one invocation per voxel: the voxelization's sums into level 0 of the
// chain and of the opacity image (voxel_common.glsl). A marked voxel is opaque (a = 1) for rays
// along all six directions; its radiance is what a diffuse surface of its mean colour and normal
// reflects under the light, and a ray sees it only where that surface faces the ray (see
// facing()): albedo x E x max(0, -n . l) / pi x visibility.
// Only the side a face's normal faces is lit: with both (|n . l|) the dark face of a wall thinner
// than 2.5 voxels passed the shadow test below and glowed (a 0.2 m wall at 13 cm voxels lit the
// floor on its shadowed side at 1.35 W/m^2 under a 10 W/m^2 sun); a voxel whose normals cancel
// out (both faces of a thin wall) reflects nothing. Visibility: lighting.deferred's 3x3
// percentage-closer filter at the voxel's centre moved one voxel out along the normal, with a
// depth bias of 1.5 voxels: a voxel's centre may lie up to sqrt(3)/2 voxels behind the surface it
// holds.
// With the environment's SH linked, a second injection after the sky visibility (voxel_sky.comp)
// adds what the sky gives the same surface: albedo x E_sky(n) x visibility / pi, E_sky from the
// cosine-convolved SH (as lighting.ibl's diffuse light), the visibility from the voxels' opacity;
// with local lights, albedo x E_local / pi (voxel_local_lights.comp); with more than one bounce,
// albedo x E_bounced / pi, the light the chain held gathered by the voxel (voxel_bounce.comp).
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/common/shaders/finite.glsl"
#define LG_SKY_SH_BINDING 7
#include "nodes/gi/common/shaders/sky_sh.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer Grid { int grid[]; };
layout(binding = 2) uniform sampler2D shadow_map;
// Level 0 of the chain and of the opacity image (voxel_common.glsl).
layout(binding = 3, rgba16f) uniform writeonly image3D seen_x;
layout(binding = 4, rgba16f) uniform writeonly image3D seen_y;
layout(binding = 5, rgba16f) uniform writeonly image3D seen_z;
layout(binding = 6, rgba16f) uniform writeonly image3D opacity_image;
layout(push_constant) uniform Push {
  // 0: the sun's light alone; bit 0: add the sky's (the sums hold its visibility), bit 1: add the
  // local lights' (the sums hold their irradiance), bit 2: add the bounced light's (likewise)
  int second;
};

// How much of a surface of unit normal n faces rays travelling along each axis the positive way
// (negative = 0) or the negative way: 1 from 15 degrees off edge-on, falling linearly to 0
// edge-on (a ray only ever meets surfaces whose normal is against its travel). A sunlit roof
// faces no ray travelling up or sideways, so rays in the rooms below cannot see it in a coarse
// voxel that also holds the ceiling's dark underside; the lit face of a thin wall faces no ray
// coming from its dark side. A voxel whose normals cancel (both faces of a slab thinner than a
// voxel, or zero-area triangles) reflects nothing: it faces every ray, dark and opaque.
vec3 facing(vec3 n, int negative) {
  if (n == vec3(0.0)) return vec3(1.0);
  return clamp((negative == 1 ? n : -n) * 3.8637033, 0.0, 1.0);  // 1 / sin 15 deg
}

// An empty voxel: opacity 0, so nothing faces anything.
void store(ivec3 c, vec3 radiance, vec3 n, float opacity) {
  for (int negative = 0; negative < 2; ++negative) {
    ivec3 t = voxel_chain_texel(c, voxel.counts.xyz, negative);
    vec3 f = opacity * facing(n, negative);
    imageStore(seen_x, t, vec4(radiance * f.x, f.x));
    imageStore(seen_y, t, vec4(radiance * f.y, f.y));
    imageStore(seen_z, t, vec4(radiance * f.z, f.z));
    imageStore(opacity_image, t, vec4(vec3(opacity), 1.0));  // alpha unused
  }
}

float visibility(vec3 p) {
  vec4 clip = voxel.shadow_from_world * vec4(p, 1.0);
  vec2 uv = clip.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  mat4 m = voxel.shadow_from_world;
  float bias = 1.5 * voxel.origin_cell.w * length(vec3(m[0][2], m[1][2], m[2][2]));  // depth per metre
  ivec2 size = textureSize(shadow_map, 0);
  ivec2 center = ivec2(uv * vec2(size));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      ivec2 t = clamp(center + ivec2(x, y), ivec2(0), size - 1);
      lit += texelFetch(shadow_map, t, 0).r > clip.z + bias ? 0.0 : 1.0;
    }
  return lit / 9.0;
}

void main() {
  ivec3 c = voxel_invocation_cell(voxel.counts.xyz);
  if (any(greaterThanEqual(c, voxel.counts.xyz))) return;
  uint base = LG_VOXEL_INTS * voxel_index(c);
  int triangles = grid[base + 6u];
  if (triangles <= 0) {
    store(c, vec3(0.0), vec3(0.0), 0.0);
    return;
  }
  float to_unit = 1.0 / (float(triangles) * kVoxelUnit);
  vec3 albedo = vec3(grid[base], grid[base + 1u], grid[base + 2u]) * to_unit;
  vec3 n = vec3(grid[base + 3u], grid[base + 4u], grid[base + 5u]) * to_unit;
  vec3 l = voxel.light.xyz;
  float len = length(n);
  vec3 radiance = vec3(0.0);
  n = len > 1e-3 ? n / len : vec3(0.0);
  if (len > 1e-3 && voxel.light.w > 0.0) {
    float cosine = max(0.0, -dot(n, l));
    vec3 centre = voxel.origin_cell.xyz + (vec3(c) + 0.5) * voxel.origin_cell.w;
    float v = cosine > 0.0 ? visibility(centre + n * voxel.origin_cell.w) : 0.0;
    radiance = albedo * voxel.irradiance.rgb * (cosine * v / LG_PI);
  }
  if (len > 1e-3 && (second & 1) != 0) radiance += albedo * sky_irradiance(n) * (intBitsToFloat(grid[base + 7u]) / LG_PI);
  if (len > 1e-3 && (second & 2) != 0) {
    vec3 local = vec3(intBitsToFloat(grid[base + 8u]), intBitsToFloat(grid[base + 9u]), intBitsToFloat(grid[base + 10u]));
    radiance += albedo * local / LG_PI;
  }
  if (len > 1e-3 && (second & 4) != 0) {
    vec3 bounced = vec3(intBitsToFloat(grid[base + 11u]), intBitsToFloat(grid[base + 12u]), intBitsToFloat(grid[base + 13u]));
    radiance += albedo * bounced / LG_PI;
  }
  store(c, clamp(finite_or_zero(radiance), 0.0, 65504.0), n, 1.0);
}
