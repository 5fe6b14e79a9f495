#version 460
#extension GL_GOOGLE_include_directive : require
// env.specular_prefilter's exact sums (prefilter_exact.comp) read the levels this builds in
// tmp.chain, one dispatch per level. rgb is the radiance, a the texel's exact solid angle times
// size^2 / 4 (in [0.19, 1], so half precision keeps it at any face size).
// Level 0 is the input's mip 0 (non-finite radiance as 0). On the peak level, the first of at
// most 128^2 a face (the finest the sums read: exact_prefilter.cpp), the peaks are taken out:
// every channel above 32 times the brightest channel of the environment's mean radiance (the
// input's last mip, 1x1) is clamped there, and the excess, times the texel's solid angle, goes
// to the peak list, which the sums add exactly at the texel's own direction. A sun is then never
// blurred with its neighbours into a coarse texel whose centre it is not at (without the list,
// grace.hdr at roughness 0.5 summed over 16^2 faces was off by 3.3%); what stays in the levels
// below is within 32x its mean. A texel past the list's capacity stays unclamped (still counted,
// only less precisely, and which texels got a slot then depends on the order the GPU ran them
// in), so nothing is lost when an environment has more peaks than the list holds. Taking them at
// 128^2 a face keeps their number independent of the input's size.
// Each further level is the solid-angle-weighted mean of the 2x2 texels it covers (the radiance's
// mean over its area: every level holds the same integral).
#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray finer;  // level 0: the input's mip 0; else the level above
layout(binding = 1, rgba16f) uniform writeonly image2DArray level;
layout(binding = 2) uniform samplerCube env;  // the input, for its mean (last mip)
layout(binding = 3, std430) buffer Peaks {
  uint peak_count;     // zeroed before the first level; may pass capacity (those stay in the chain)
  uint peak_capacity;  // written by the host
  uint pad0, pad1;
  vec4 peaks[];  // per peak: direction (xyz), then flux (rgb: excess radiance x solid angle)
};
layout(push_constant) uniform Push {
  uint first;       // 1: level 0, from the input
  uint peak_level;  // 1: the level the peaks are taken from
};

// Bound on what stays in the chain, in units of the mean's brightest channel. On 128^2 cubes
// grace.hdr has 407 texels above 32 (RMS error at roughness 0.25 / 0.5 / 0.75 / 1 0.100% /
// 0.048% / 0.111% / 0.086%), 806 above 16 (more than the list holds) and 190 above 64 (0.106% /
// 0.052% / 0.119% / 0.097%); the random environment 72, pisa.hdr none.
const float kPeakBound = 32.0;

// The nearest value an rgba16f texel holds: lavapipe's stores round toward zero, which would
// bias each level made from the one above.
vec3 nearest_half(vec3 c) {
  return uintBitsToFloat((floatBitsToUint(c) + 0x1000u) & ~0x1FFFu);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(level).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  float solid_angle = cube_texel_solid_angle(texel, size);
  vec3 radiance;
  if (first != 0u) {
    radiance = finite_or_zero(texelFetch(finer, ivec3(texel, face), 0).rgb);
  } else {
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      vec4 child = texelFetch(finer, ivec3(2 * texel + ivec2(k & 1, k >> 1), face), 0);
      sum += child.rgb * child.a;
      weight += child.a;
    }
    radiance = sum / weight;
  }
  if (peak_level != 0u) {
    vec3 mean = finite_or_zero(textureLod(env, vec3(0.0, 0.0, 1.0), float(textureQueryLevels(env) - 1)).rgb);
    // Rounded to half, so the clamped radiance is exactly what the chain stores.
    float bound = nearest_half(vec3(kPeakBound * max(max(mean.r, mean.g), mean.b))).x;
    vec3 kept = min(radiance, vec3(bound));
    if (bound > 0.0 && any(greaterThan(radiance, kept))) {
      uint slot = atomicAdd(peak_count, 1u);
      if (slot < peak_capacity) {
        peaks[2u * slot] = vec4(cube_direction(face, (vec2(texel) + 0.5) / float(size)), 0.0);
        peaks[2u * slot + 1u] = vec4((radiance - kept) * solid_angle, 0.0);
        radiance = kept;
      }
    }
  }
  imageStore(level, ivec3(texel, face), vec4(nearest_half(radiance), solid_angle * float(size * size) * 0.25));
}
