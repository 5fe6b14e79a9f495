#version 460
#extension GL_GOOGLE_include_directive : require
// Writes the nearest surface's bake: the interpolated vertex bake, or the lightmap sampled
// bilinearly (texel centres at (i + 0.5) / size, indices clamped to the edge; the bake's padding
// texels keep chart edges right), its bent normal turned to world space and normalised.
// Surfaces without a bake write w = -1. Mirrored in double by nodes/occlusion/baked/baked_reference.h.
#include "nodes/occlusion/baked/shaders/baked_draw.glsl"

layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec4 vertex_bake;
layout(location = 2) in vec2 lightmap_uv;

layout(location = 0) out vec4 out_baked;

vec4 lightmap_texel(BakedDraw b, ivec2 t) {
  ivec2 c = clamp(t, ivec2(0), ivec2(int(b.lightmap_size) - 1));
  return lightmap_texels[b.lightmap_base + uint(c.y) * b.lightmap_size + uint(c.x)];
}

vec4 lightmap_bilinear(BakedDraw b, vec2 uv) {
  vec2 p = uv * float(b.lightmap_size) - 0.5;
  ivec2 t = ivec2(floor(p));
  vec2 f = p - vec2(t);
  return mix(mix(lightmap_texel(b, t), lightmap_texel(b, t + ivec2(1, 0)), f.x),
             mix(lightmap_texel(b, t + ivec2(0, 1)), lightmap_texel(b, t + ivec2(1, 1)), f.x), f.y);
}

void main() {
  BakedDraw b = baked_draws[draw_index];
  if (b.kind == kNoBake) {
    out_baked = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }
  vec4 v = vertex_bake;
  if (b.kind == kTexelBake) {
    v = lightmap_bilinear(b, lightmap_uv);
    v.xyz = mat3(b.lightmap_to_world) * v.xyz;
  }
  float len = length(v.xyz);
  vec3 n = normalize(world_normal);
  if (!gl_FrontFacing) n = -n;  // as the G-buffer stores two-sided surfaces
  out_baked = vec4(len > 1e-6 ? v.xyz / len : n, clamp(v.w, 0.0, 1.0));
}
