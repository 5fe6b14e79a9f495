// Joint bilateral upsampling (Kopf et al. 2007) guided by the G-buffer: an image computed at
// `scale` of the G-buffer's resolution (its texel i at G-buffer texel upsample_source_texel(i))
// brought back to full resolution. Each full-resolution pixel blends the 2 x 2 low-resolution
// texels around it with bilinear weights times how alike their surfaces are (view distance and
// normal), so that smooth light is interpolated along a surface but not across its silhouette or
// crease. Where no texel around is alike (a surface thinner than the low-resolution step) the
// most alike one is taken; where every texel around is sky, 0. For any pass that computes smooth
// light at a fraction of the resolution (the irradiance volume lookup; post.upsample).
#ifndef LG_JOINT_UPSAMPLE_GLSL
#define LG_JOINT_UPSAMPLE_GLSL

#include "nodes/common/shaders/gbuffer.glsl"

// The G-buffer texel that low-resolution texel `low` stands for.
ivec2 upsample_source_texel(ivec2 low, float scale, ivec2 full_size) {
  return min(ivec2(vec2(low) / scale), full_size - 1);
}

// Surfaces count as alike within a few per cent of relative view distance (reversed-Z depth is
// proportional to 1 / distance, so |d_tap - d| / d_tap is the relative change in distance; a floor
// seen at 5 degrees changes by ~2% between texels two pixels apart) and within ~30 degrees of
// normal (cos^8 of 30 degrees is 0.32).
const float LG_UPSAMPLE_DISTANCE_SIGMA = 0.05;
const float LG_UPSAMPLE_NORMAL_POWER = 8.0;

vec4 joint_upsample(sampler2D low_tex, sampler2D depth_tex, sampler2D normal_tex, ivec2 texel, float scale) {
  float depth = texelFetch(depth_tex, texel, 0).r;
  if (depth <= 0.0) return vec4(0.0);
  vec3 n = decode_normal(texelFetch(normal_tex, texel, 0).rgb);
  ivec2 low_size = textureSize(low_tex, 0), full_size = textureSize(depth_tex, 0);
  vec2 u = vec2(texel) * scale;
  ivec2 base = ivec2(floor(u));
  vec2 f = u - vec2(base);
  vec4 sum = vec4(0.0), best = vec4(0.0);
  float total = 0.0, best_unlikeness = 1e30;
  for (int k = 0; k < 4; ++k) {
    ivec2 step = ivec2(k & 1, k >> 1);
    ivec2 low = min(base + step, low_size - 1);
    ivec2 source = upsample_source_texel(low, scale, full_size);
    float tap_depth = texelFetch(depth_tex, source, 0).r;
    if (tap_depth <= 0.0) continue;
    float distance_change = abs(tap_depth - depth) / tap_depth / LG_UPSAMPLE_DISTANCE_SIGMA;
    float facing = max(dot(n, decode_normal(texelFetch(normal_tex, source, 0).rgb)), 0.0);
    vec4 value = texelFetch(low_tex, low, 0);
    // Ranked without the exponential, which underflows to 0 for every tap across an edge.
    float unlikeness = distance_change * distance_change - LG_UPSAMPLE_NORMAL_POWER * log(max(facing, 1e-30));
    if (unlikeness < best_unlikeness) {
      best_unlikeness = unlikeness;
      best = value;
    }
    vec2 b = mix(1.0 - f, f, vec2(step));
    float weight = b.x * b.y * exp(-unlikeness);
    sum += weight * value;
    total += weight;
  }
  // 1e-3: below it the bilinear neighbours are all unlike the pixel and their blend is noise.
  return total > 1e-3 ? sum / total : best;
}

#endif
