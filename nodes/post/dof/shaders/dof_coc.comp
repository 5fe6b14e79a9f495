#version 460
#extension GL_GOOGLE_include_directive : require
// The signed circle of confusion of a thin lens at every pixel, in full-resolution pixels:
// negative in front of the focus plane, positive behind it, clamped to the largest blur.
#include "nodes/post/dof/shaders/dof_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D device_depth;
layout(binding = 1, rgba16f) uniform writeonly image2D coc;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(coc)))) return;
  float d = texelFetch(device_depth, texel, 0).r;
  // 1 / z = d / near; the sky (d = 0) is at infinity.
  float inverse_z = max(d, 0.0) / near_plane;
  float radius = coc_scale * (1.0 / focus - inverse_z);
  imageStore(coc, texel, vec4(clamp(radius, -max_blur, max_blur), 0.0, 0.0, 1.0));
}
