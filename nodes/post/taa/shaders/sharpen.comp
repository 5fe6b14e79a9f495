#version 460
#extension GL_GOOGLE_include_directive : require
// post.taa's output: an unsharp mask of the accumulated image, c + s (c - mean of its four
// neighbours), worked out after the reversible tone map (so a highlight does not ring into its
// surroundings) and kept within the five pixels' range (no new over- or undershoot). At
// strength 0 it is a copy. The history keeps the unsharpened image.
#include "nodes/post/taa/shaders/taa_color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D accumulated;  // nearest
layout(binding = 1, rgba16f) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  float strength;
};

void main() {
  ivec2 size = imageSize(result);
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, size))) return;
  vec3 c = texelFetch(accumulated, texel, 0).rgb;
  if (strength > 0.0) {
    vec3 t = compress(c), lo = t, hi = t, around = vec3(0.0);
    const ivec2 offsets[4] = ivec2[](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    for (int i = 0; i < 4; ++i) {
      vec3 n = compress(texelFetch(accumulated, clamp(texel + offsets[i], ivec2(0), size - 1), 0).rgb);
      around += n;
      lo = min(lo, n);
      hi = max(hi, n);
    }
    c = expand(clamp(t + strength * (t - 0.25 * around), lo, hi));
  }
  imageStore(result, texel, vec4(c, 1.0));
}
