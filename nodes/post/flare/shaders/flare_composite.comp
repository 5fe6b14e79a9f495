#version 460
#extension GL_GOOGLE_include_directive : require
// post.flare's composite: the image (NaN and Inf as black) plus intensity x the guarded flare,
// upsampled bilinearly from the grid with the texel indices clamped to it, over the whole
// blocks only: there every grid texel's weights sum to divisor^2, so this pass adds exactly
// intensity x divisor^2 x the grid's flare, no more (nodes/post/flare/flare_model.h).
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D flare;
layout(binding = 2) uniform sampler2D guard;  // 1x1: the factor of flare_normalise.comp
layout(binding = 3, rgba16f) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  float intensity;
  int divisor;
};

// Texel fetches, not the sampler's filter: its weights may be fixed point, and the sums above
// hold for exact ones.
vec3 upsampled(ivec2 pixel) {
  ivec2 last = textureSize(flare, 0) - 1;
  vec2 t = clamp((vec2(pixel) + 0.5) / float(divisor) - 0.5, vec2(0.0), vec2(last));
  ivec2 t0 = ivec2(t), t1 = min(t0 + 1, last);
  vec2 w = t - vec2(t0);
  return mix(mix(texelFetch(flare, t0, 0).rgb, texelFetch(flare, ivec2(t1.x, t0.y), 0).rgb, w.x),
             mix(texelFetch(flare, ivec2(t0.x, t1.y), 0).rgb, texelFetch(flare, t1, 0).rgb, w.x), w.y);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(result)))) return;
  vec3 c = finite_or_zero(texelFetch(scene_color, pixel, 0).rgb);
  if (all(lessThan(pixel, textureSize(flare, 0) * divisor)))
    c += intensity * texelFetch(guard, ivec2(0), 0).r * upsampled(pixel);
  imageStore(result, pixel, vec4(c, 1.0));
}
