// Joint bilateral upsampling (Kopf et al. 2007) guided by the G-buffer: an image computed at
// 1/k of the G-buffer's resolution (k a whole number; its texel i computed at G-buffer texel
// upsample_source_texel(i, k)) brought back to full resolution. Each full-resolution pixel
// blends the 2 x 2 low-resolution texels around it with bilinear weights times how alike their
// surfaces are to its own (view distance and normal), so that smooth light is interpolated along
// a surface but not across a silhouette or crease; where none is alike (a surface thinner than
// k pixels) the most alike one is taken, and where all four are sky, 0.
// Work goes by low-resolution texel: every pixel of the k x k block that starts at k * i blends
// the same four texels, so a caller reads them once (upsample_taps) and then each pixel of the
// block (upsample_pixel, upsample_block_end): on lavapipe the texel fetches are the cost, and
// this reads 2 + 12 / k^2 a pixel (5 at k = 2) instead of 14. For any pass that computes smooth light at a
// fraction of the resolution (the irradiance volume lookup, GTAO, post.upsample).
#ifndef LG_JOINT_UPSAMPLE_GLSL
#define LG_JOINT_UPSAMPLE_GLSL

#include "nodes/common/shaders/gbuffer.glsl"

// The G-buffer texel that low-resolution texel `low` stands for.
ivec2 upsample_source_texel(ivec2 low, int k, ivec2 full_size) {
  return min(low * k, full_size - 1);
}

// One past the last pixel of texel `low`'s block: k pixels on, except that the last row and
// column of texels also take the pixels past k * low_size up to the image's edge.
ivec2 upsample_block_end(ivec2 low, int k, ivec2 low_size, ivec2 full_size) {
  return mix(min((low + 1) * k, full_size), full_size, equal(low, low_size - 1));
}

// Where G-buffer pixel `texel` of texel `low`'s block lies between tap 0 and tap 3 (the `f` of
// upsample_weights); pixels past the last texel take the edge's.
vec2 upsample_fraction(ivec2 texel, ivec2 low, int k) {
  return min(vec2(texel - low * k) / float(k), vec2(1.0));
}

// Surfaces count as alike within a few per cent of view distance (reversed-Z depth is
// proportional to 1 / distance, so |d_tap - d| / d_tap is the relative change in distance; a floor
// seen at 5 degrees changes by ~2% between texels two pixels apart) and within ~30 degrees of
// normal (cos^8 of 30 degrees is 0.32). Rational, not Gaussian, in distance: the ranking of taps
// that are all unlike must not underflow to 0.
const float LG_UPSAMPLE_DISTANCE_SCALE = 0.05;

// Where the 2 x 2 low-resolution texels around a block stand: their surfaces (G-buffer depth
// and normal at their source texels), which decide every pixel's weights.
struct UpsampleGuide {
  float depth[4];  // texels low, low + (1, 0), low + (0, 1), low + (1, 1), clamped; 0: sky
  float distance_scale[4];  // 1 / (depth LG_UPSAMPLE_DISTANCE_SCALE), 0 for sky
  vec3 normal[4];  // unnormalized (decode_normal_unnormalized): the dot products need no more
};

// Sets tap t of `guide` to the surface with G-buffer depth `depth` (0: sky) and normal n
// (unnormalized, or unit). For a caller that keeps each texel's surface beside its values
// (occlusion.gtao) and so fetches no G-buffer texels for the guide.
void upsample_guide_tap(inout UpsampleGuide guide, int t, float depth, vec3 n) {
  guide.depth[t] = depth;
  guide.distance_scale[t] = depth > 0.0 ? 1.0 / (depth * LG_UPSAMPLE_DISTANCE_SCALE) : 0.0;
  guide.normal[t] = n;
}

UpsampleGuide upsample_guide(sampler2D depth_tex, sampler2D normal_tex, ivec2 low, int k, ivec2 low_size) {
  ivec2 full_size = textureSize(depth_tex, 0);
  UpsampleGuide guide;
  for (int t = 0; t < 4; ++t) {
    ivec2 source = upsample_source_texel(min(low + ivec2(t & 1, t >> 1), low_size - 1), k, full_size);
    upsample_guide_tap(guide, t, texelFetch(depth_tex, source, 0).r,
                       decode_normal_unnormalized(texelFetch(normal_tex, source, 0).rgb));
  }
  return guide;
}

// Tap t's bilinear weight (t = 0..3 as the guide's) for the pixel at fraction `f`.
float upsample_bilinear(int t, vec2 f) {
  vec2 b = mix(1.0 - f, f, vec2(t & 1, t >> 1));
  return b.x * b.y;
}

// How alike in normal each tap's surface is to one with normal n (unnormalized, as the guide's):
// cos^8 of the angle between them.
vec4 upsample_facing(UpsampleGuide guide, vec3 n) {
  vec4 facing;
  for (int t = 0; t < 4; ++t) facing[t] = max(dot(n, guide.normal[t]), 0.0);
  facing *= facing;
  facing *= facing;
  return facing * facing;
}

// The weights of the four taps (summing to 1) for the pixel at fraction `f` (in [0, 1)) of the
// way from tap 0 toward tap 3, with G-buffer depth `depth` (> 0) and the taps' likeness in
// normal `facing` (upsample_facing; all 1 to weigh by depth alone); all 0 where every tap is
// sky. Callers that upsample several images at once apply one set of weights to each.
vec4 upsample_weights_facing(UpsampleGuide guide, float depth, vec4 facing, vec2 f) {
  vec4 weights = vec4(0.0);
  float total = 0.0, best_rank = 0.0;
  int best = -1;
  for (int t = 0; t < 4; ++t) {
    if (guide.depth[t] <= 0.0) continue;
    float q = abs(guide.depth[t] - depth) * guide.distance_scale[t];
    float near = 1.0 / (1.0 + q * q);
    float alike = near * near * facing[t];
    float rank = alike + 1e-6 * near;  // faces turned away still rank by distance
    if (rank > best_rank) {
      best_rank = rank;
      best = t;
    }
    weights[t] = upsample_bilinear(t, f) * alike;
    total += weights[t];
  }
  // Below 1e-3 the bilinear neighbours are all unlike the pixel and their blend is noise.
  if (total > 1e-3) return weights / total;
  vec4 one_hot = vec4(0.0);
  if (best >= 0) one_hot[best] = 1.0;
  return one_hot;
}

// The same, alike in view distance and normal n (unnormalized, as the guide's).
vec4 upsample_weights(UpsampleGuide guide, float depth, vec3 n, vec2 f) {
  return upsample_weights_facing(guide, depth, upsample_facing(guide, n), f);
}

struct UpsampleTaps {
  vec4 value[4];  // the low-resolution texels the guide stands for
  UpsampleGuide guide;
};

UpsampleTaps upsample_taps(sampler2D low_tex, sampler2D depth_tex, sampler2D normal_tex, ivec2 low, int k) {
  ivec2 low_size = textureSize(low_tex, 0);
  UpsampleTaps taps;
  taps.guide = upsample_guide(depth_tex, normal_tex, low, k, low_size);
  for (int t = 0; t < 4; ++t) taps.value[t] = texelFetch(low_tex, min(low + ivec2(t & 1, t >> 1), low_size - 1), 0);
  return taps;
}

// One image's pixel (upsample_weights says which); 0 where every tap is sky.
vec4 upsample_pixel(UpsampleTaps taps, float depth, vec3 n, vec2 f) {
  vec4 w = upsample_weights(taps.guide, depth, n, f);
  return w.x * taps.value[0] + w.y * taps.value[1] + w.z * taps.value[2] + w.w * taps.value[3];
}

#endif
