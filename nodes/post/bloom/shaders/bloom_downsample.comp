#version 460
#extension GL_GOOGLE_include_directive : require
// One level of the bloom chain from the level above (or from the scene at level 0): a 4x4
// box as four bilinear taps. Level 0 also applies the threshold: only the part of each texel's
// radiance above it blooms (all of it when the threshold is 0).
#include "nodes/common/shaders/bright_part.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Push {
  float threshold;  // luminance; 0 for none
  uint first;       // 1 when reading the scene
};

// NaN and Inf would spread over the whole chain: they count as black.
vec3 finite(vec3 c) {
  return any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : min(c, vec3(65504.0));
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(target);
  if (any(greaterThanEqual(texel, size))) return;
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  vec2 step_uv = 1.0 / vec2(textureSize(source, 0));
  vec3 sum = vec3(0.0);
  for (int y = -1; y <= 1; y += 2)
    for (int x = -1; x <= 1; x += 2) {
      vec3 c = finite(textureLod(source, uv + vec2(x, y) * step_uv, 0.0).rgb);
      sum += first != 0u ? bright_part(c, threshold) : c;
    }
  imageStore(target, texel, vec4(sum * 0.25, 1.0));
}
