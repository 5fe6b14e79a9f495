#version 460
#extension GL_GOOGLE_include_directive : require
// post.bilateral's full kernel: every tap of the (2 radius + 1)^2 square around the pixel,
// weighted jointly by screen distance, view distance and normal (bilateral_common.glsl). The
// reference the separable form is measured against; (2r + 1)^2 taps a pixel.
#include "nodes/post/bilateral/shaders/bilateral_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(result)))) return;
  BilateralCentre c = bilateral_centre(texel);
  if (bilateral_pass_sky(c)) return;
  vec4 sum = vec4(0.0);
  for (int y = -radius; y <= radius; ++y)
    for (int x = -radius; x <= radius; ++x) sum += bilateral_tap(c, ivec2(x, y));
  bilateral_store(texel, sum);
}
