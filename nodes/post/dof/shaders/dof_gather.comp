#version 460
#extension GL_GOOGLE_include_directive : require
// The blurred image at half resolution, gathered over a disc of the largest blur: each tap
// counts where its own circle of confusion reaches this pixel (scatter as gather), and taps in
// front of the focus plane also blur over sharper background.
#include "nodes/post/dof/shaders/dof_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D coc;
layout(binding = 2, rgba16f) uniform writeonly image2D blurred;

const float GOLDEN_ANGLE = 2.39996323;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(blurred);
  if (any(greaterThanEqual(texel, size))) return;
  vec2 full = vec2(textureSize(scene_color, 0));
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  float centre = texelFetch(coc, ivec2(uv * full), 0).r;
  vec4 sum = vec4(0.0);
  for (uint i = 0u; i < samples; ++i) {
    // Vogel's spiral: evenly spread taps over the disc for any count.
    float r = sqrt((float(i) + 0.5) / float(samples)) * max_blur;
    float a = float(i) * GOLDEN_ANGLE;
    vec2 tap = uv + vec2(cos(a), sin(a)) * r / full;
    vec3 c = textureLod(scene_color, tap, 0.0).rgb;
    float tap_coc = textureLod(coc, tap, 0.0).r;
    // The CoC grows with distance: a tap farther than the centre cannot blur over it by more
    // than the centre's own blur (a sharp foreground stays sharp); a nearer one spreads fully.
    float reach = tap_coc > centre ? min(abs(tap_coc), abs(centre)) : abs(tap_coc);
    float w = clamp(reach - r + 1.0, 0.0, 1.0);
    if (any(isnan(c)) || any(isinf(c))) w = 0.0;
    sum += vec4(c * w, w);
  }
  vec3 colour = sum.w > 0.0 ? sum.rgb / sum.w : textureLod(scene_color, uv, 0.0).rgb;
  imageStore(blurred, texel, vec4(colour, sum.w / float(max(samples, 1u))));
}
