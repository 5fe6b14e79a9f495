#version 460
#extension GL_GOOGLE_include_directive : require
// One pass of post.bilateral's separable form: the 2 radius + 1 taps along `direction`, rows
// and then columns of the rows' result, 2 (2r + 1) taps a pixel instead of (2r + 1)^2. Each
// pass weighs its taps against its own centre's surface, so a tap reached diagonally is
// weighed against the surface of the pixel between: exact where the guide is uniform, an
// approximation at edges (its error against the full kernel is measured, README).
#include "nodes/post/bilateral/shaders/bilateral_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(result)))) return;
  BilateralCentre c = bilateral_centre(texel);
  if (bilateral_pass_sky(c)) return;
  vec4 sum = vec4(0.0);
  for (int i = -radius; i <= radius; ++i) sum += bilateral_tap(c, i * direction);
  bilateral_store(texel, sum);
}
