// What post.bilateral's passes share: the push constants (bilateral_kernel.cpp fills them) and
// the joint bilateral weight of a tap, a Gaussian in screen distance, in relative view distance
// and in normal difference to the centre pixel's surface (the G-buffer guides; the image does
// not). Taps on the sky, outside the image or with a NaN or Inf channel weigh 0.
#ifndef LG_BILATERAL_COMMON_GLSL
#define LG_BILATERAL_COMMON_GLSL

#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/gbuffer.glsl"

layout(push_constant) uniform Push {
  int radius;             // taps reach radius pixels each way
  float spatial_falloff;  // 1 / (2 sigma_spatial^2), per pixel^2
  float depth_falloff;    // 1 / (2 sigma_depth^2)
  float normal_falloff;   // 1 / (2 sigma_normal^2)
  ivec2 direction;        // the separable form's pass: (1, 0) rows, (0, 1) columns
  int coverage_in_alpha;  // 1: a source texel of alpha 0 holds no value (the rows pass's output)
};

layout(binding = 0) uniform sampler2D source;  // the image filtered (in the columns pass: the rows pass's)
layout(binding = 1) uniform sampler2D color;   // the node's input, which sky pixels pass through
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 3) uniform sampler2D normal_tex;
layout(binding = 4, rgba16f) uniform writeonly image2D result;

// The centre pixel's surface; reversed-Z depth 0 is the sky.
struct BilateralCentre {
  ivec2 texel;
  float depth;
  vec3 normal;
};

BilateralCentre bilateral_centre(ivec2 texel) {
  return BilateralCentre(texel, texelFetch(depth_tex, texel, 0).r, decode_normal(texelFetch(normal_tex, texel, 0).rgb));
}

// The tap at `offset` from the centre, as (weight * colour, weight). Reversed-Z depth is
// proportional to 1 / distance, so (d_tap - d) / d_tap is the relative change in view distance;
// |n_tap - n|^2 = 2 - 2 cos(angle) for unit normals, about the angle squared when small.
vec4 bilateral_tap(BilateralCentre c, ivec2 offset) {
  ivec2 t = c.texel + offset;
  if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, textureSize(depth_tex, 0)))) return vec4(0.0);
  float tap_depth = texelFetch(depth_tex, t, 0).r;
  if (!(tap_depth > 0.0)) return vec4(0.0);
  vec4 value = texelFetch(source, t, 0);
  if (!all_finite(value) || (coverage_in_alpha != 0 && value.a <= 0.0)) return vec4(0.0);
  float q = (tap_depth - c.depth) / tap_depth;
  vec3 dn = decode_normal(texelFetch(normal_tex, t, 0).rgb) - c.normal;
  float w = exp(-(float(dot(offset, offset)) * spatial_falloff + q * q * depth_falloff + dot(dn, dn) * normal_falloff));
  return vec4(value.rgb * w, w);
}

// Returns whether the centre is sky, after writing it: the sky has no surface to guide the
// weights, so it passes through unfiltered (NaN and Inf as 0), and no surface takes its colour.
bool bilateral_pass_sky(BilateralCentre c) {
  if (c.depth > 0.0) return false;
  imageStore(result, c.texel, vec4(finite_or_zero(texelFetch(color, c.texel, 0).rgb), 1.0));
  return true;
}

// The weighted mean, alpha 1; where no tap counted (every one NaN, Inf or uncovered), 0 with
// alpha 0, which the columns pass reads as no value.
void bilateral_store(ivec2 texel, vec4 sum) {
  imageStore(result, texel, sum.w > 0.0 ? vec4(sum.rgb / sum.w, 1.0) : vec4(0.0));
}

#endif
