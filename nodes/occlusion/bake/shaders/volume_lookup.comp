#version 460
#extension GL_GOOGLE_include_directive : require
// occlusion.bake per pixel: the baked visibility grid (vec4(m, v) per point, the L1 spherical-
// harmonic projection of visibility, V(w) ~ v + 3 m . w; w = -1 inside geometry or on a surface) sampled
// trilinearly by hand at p + n * offset over valid points only, then turned into the
// cosine-weighted visibility about n and the bent normal with its cone cosine. The same
// formulas in double: nodes/occlusion/bake/volume_lookup.h, which the tests compare against.
#include "nodes/common/shaders/camera.glsl"
#include "nodes/common/shaders/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform Constants {
  Camera camera;
  vec4 grid_origin;   // xyz: the first point; w: the lookup's offset along the normal (m)
  vec4 grid_spacing;  // xyz: between points (m)
  uvec4 grid_dims;    // xyz: points per axis, all 0 without geometry
};
layout(binding = 1) uniform sampler2D gbuffer_depth;
layout(binding = 2) uniform sampler2D gbuffer_normal;
layout(std430, binding = 3) readonly buffer Grid {
  vec4 points[];
};
layout(binding = 4, r8) uniform writeonly image2D ao_out;
layout(binding = 5, rgba8_snorm) uniform writeonly image2D bent_out;

const float kMinWeight = 1e-4;  // volume_lookup_min_weight

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(ao_out)))) return;
  float depth = texelFetch(gbuffer_depth, texel, 0).r;
  if (!(depth > 0.0)) {  // the sky
    imageStore(ao_out, texel, vec4(1.0));
    imageStore(bent_out, texel, vec4(0.0));
    return;
  }
  vec3 p = world_position(camera, texel, depth);
  vec3 n = decode_normal(texelFetch(gbuffer_normal, texel, 0).rgb);
  float weight = 0.0, v = 0.0;
  vec3 m = vec3(0.0);
  if (grid_dims.x > 0u) {
    vec3 last = vec3(grid_dims.xyz - 1u);
    vec3 g = clamp((p + n * grid_origin.w - grid_origin.xyz) / grid_spacing.xyz, vec3(0.0), last);
    uvec3 lo = min(uvec3(g), grid_dims.xyz - 2u);
    vec3 f = g - vec3(lo);
    for (uint corner = 0u; corner < 8u; ++corner) {
      uvec3 c = lo + uvec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
      vec4 point = points[(c.z * grid_dims.y + c.y) * grid_dims.x + c.x];
      if (point.w < 0.0) continue;  // inside geometry or on a surface
      vec3 t = mix(1.0 - f, f, vec3(c - lo));
      float w = t.x * t.y * t.z;
      weight += w;
      v += w * point.w;
      m += w * point.xyz;
    }
  }
  if (weight < kMinWeight) {
    imageStore(ao_out, texel, vec4(1.0));
    imageStore(bent_out, texel, vec4(n, 0.0));
    return;
  }
  v /= weight;
  m /= weight;
  float mn = dot(m, n);
  float ao = clamp(v + 2.0 * mn, 0.0, 1.0);
  vec3 bent = (2.0 / 3.0) * v * n + 0.75 * (m + mn * n);
  float len = length(bent);
  imageStore(ao_out, texel, vec4(ao));
  imageStore(bent_out, texel, vec4(len > 1e-8 ? bent / len : n, sqrt(1.0 - ao)));
}
