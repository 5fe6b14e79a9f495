#version 460
#extension GL_GOOGLE_include_directive : require
// Exposure, then a tone curve, then the sRGB transfer function into an rgba8 image (storage
// images cannot be sRGB, so the encoding is written out here). NaN becomes black, +Inf white.
#include "nodes/post/tonemap/shaders/tone_curves.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1, rgba8) uniform writeonly image2D display;
layout(push_constant) uniform Push {
  float exposure_scale;  // 2^EV
  uint curve;            // 0 ACES fitted, 1 neutral, 2 clamp
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(display)))) return;
  vec3 c = texelFetch(scene_color, texel, 0).rgb * exposure_scale;
  for (int i = 0; i < 3; ++i) {
    uint bits = floatBitsToUint(c[i]) & 0x7fffffffu;
    if (bits > 0x7f800000u) c[i] = 0.0;          // NaN
    else if (bits == 0x7f800000u) c[i] = c[i] > 0.0 ? 65504.0 : 0.0;  // Inf: the brightest half
  }
  c = max(c, vec3(0.0));
  vec3 mapped = curve == 0u ? aces_fitted(c) : curve == 1u ? neutral(c) : clamp(c, 0.0, 1.0);
  imageStore(display, texel, vec4(srgb_encode(mapped), 1.0));
}
