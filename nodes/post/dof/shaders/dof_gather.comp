#version 460
#extension GL_GOOGLE_include_directive : require
// The defocused layer at full resolution, gathered over a disc of the largest blur: scatter as
// gather. Each tap spreads its light evenly over its own circle of confusion, so it weighs
// 1 / (the taps its circle covers): a defocused point keeps its energy however small its circle
// is against the background's. Taps nearer than this pixel lie over what is behind, unnormalised
// (their light is exact); the rest (this pixel's own layer and what lies behind) are normalised
// and fill what the nearer taps leave uncovered. Taps count by how defocused they are, as the
// composite blends them: a pixel in focus stays in the sharp image and lends no light here.
#include "nodes/post/dof/shaders/dof_constants.glsl"
#include "nodes/post/dof/shaders/dof_blend.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D coc;
layout(binding = 2, rgba16f) uniform writeonly image2D blurred;

const float GOLDEN_ANGLE = 2.39996323;

// The taps a circle of radius R covers, each weighing clamp(R + 1 - r, 0, 1) at its distance r
// (a one-pixel ramp at the edge): the pixel's own, and the spiral's density N / (pi M^2) times
// the ramp's integral over the plane, pi (R^2 + R + 1/3). With few taps against the circle the
// pixel's own dominates, and the blur fades to the sharp image rather than to gaps.
float taps_covered(float radius) {
  return 1.0 + float(samples) * (radius * radius + radius + 1.0 / 3.0) / (max_blur * max_blur);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(blurred);
  if (any(greaterThanEqual(texel, size))) return;
  float centre = texelFetch(coc, texel, 0).r;
  vec3 own = texelFetch(scene_color, texel, 0).rgb;
  vec4 nearer = vec4(0.0);
  vec4 rest = all_finite(vec4(own, 0.0)) ? vec4(own, 1.0) * defocus_blend(abs(centre)) / taps_covered(abs(centre)) : vec4(0.0);
  for (uint i = 0u; i < samples; ++i) {
    // Vogel's spiral: evenly spread taps over the disc for any count.
    float r = sqrt((float(i) + 0.5) / float(samples)) * max_blur;
    float a = float(i) * GOLDEN_ANGLE;
    // Colour and circle from the same pixel: a bilinear colour under a nearest circle would
    // spread an in-focus edge's light by its blurred neighbour's circle.
    ivec2 tap = clamp(texel + ivec2(floor(vec2(cos(a), sin(a)) * r + 0.5)), ivec2(0), size - 1);
    vec3 c = texelFetch(scene_color, tap, 0).rgb;
    // A bad texel lends nothing (skipped: a zero weight times Inf or NaN is NaN).
    if (!all_finite(vec4(c, 0.0))) continue;
    float tap_coc = texelFetch(coc, tap, 0).r;
    float spread = abs(tap_coc);
    float w = defocus_blend(spread);
    if (tap_coc < centre - 1.0) {
      // Nearer by over a pixel of blur: spreads fully over this pixel.
      nearer += vec4(c, 1.0) * w * clamp(spread - r + 1.0, 0.0, 1.0) / taps_covered(spread);
    } else {
      // The CoC grows with distance: a tap farther than the centre cannot blur over it by more
      // than the centre's own blur (a sharp foreground stays sharp), so it weighs as a circle of
      // that size: around a small object the background then fills what the object leaves, and
      // the object's own light is not inflated by the normalisation.
      float reach = tap_coc > centre ? min(spread, abs(centre)) : spread;
      rest += vec4(c, 1.0) * w * clamp(reach - r + 1.0, 0.0, 1.0) / taps_covered(reach);
    }
  }
  vec3 behind = rest.w > 0.0 ? rest.rgb / rest.w : vec3(0.0);
  vec3 colour = nearer.rgb / max(nearer.w, 1.0) + (1.0 - min(nearer.w, 1.0)) * behind;
  imageStore(blurred, texel, vec4(colour, 1.0));
}
