#version 460
#extension GL_GOOGLE_include_directive : require
// Exposure, then a tone curve, then the sRGB transfer function into an rgba8 image (storage
// images cannot be sRGB, so the encoding is written out here). NaN becomes black, +Inf white.
// The exposure is the param's, times an automatic one (post.exposure) where linked.
#include "nodes/post/tonemap/shaders/tone_curves.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1, rgba8) uniform writeonly image2D display;
layout(binding = 2) uniform sampler2D auto_exposure_ev;  // 1x1, EV in red (post.exposure)
layout(push_constant) uniform Push {
  float exposure_scale;  // 2^EV
};
// Specialization constants, not push constants: lavapipe runs both sides of a branch on a
// uniform value, so every pixel paid for both curves and the exposure's fetch.
layout(constant_id = 0) const uint curve = 0u;             // 0 ACES fitted, 1 neutral, 2 clamp
layout(constant_id = 1) const bool auto_exposure = false;  // multiply by 2^auto_exposure_ev; false: a stand-in

// The exposure param's factor, times the automatic exposure's when linked (a non-finite one
// counts as 0 EV, so it never spreads).
float exposure_factor() {
  if (!auto_exposure) return exposure_scale;
  float ev = texelFetch(auto_exposure_ev, ivec2(0), 0).r;
  return abs(ev) < 128.0 ? exposure_scale * exp2(ev) : exposure_scale;
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(display)))) return;
  vec3 c = texelFetch(scene_color, texel, 0).rgb * exposure_factor();
  for (int i = 0; i < 3; ++i) {
    uint bits = floatBitsToUint(c[i]) & 0x7fffffffu;
    if (bits > 0x7f800000u) c[i] = 0.0;          // NaN
    else if (bits == 0x7f800000u) c[i] = c[i] > 0.0 ? 65504.0 : 0.0;  // Inf: the brightest half
  }
  c = max(c, vec3(0.0));
  vec3 mapped = curve == 0u ? aces_fitted(c) : curve == 1u ? neutral(c) : clamp(c, 0.0, 1.0);
  imageStore(display, texel, vec4(srgb_encode(mapped), 1.0));
}
