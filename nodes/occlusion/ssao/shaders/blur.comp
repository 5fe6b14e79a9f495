#version 460
#extension GL_GOOGLE_include_directive : require
// A 5x5 blur of the raw SSAO that skips neighbours at another depth (relative difference over
// 5%), so occlusion does not bleed across silhouettes.
#include "nodes/occlusion/ssao/shaders/ssao_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D gbuffer_depth;
layout(binding = 2) uniform sampler2D noisy;
layout(binding = 3, r8) uniform writeonly image2D ao;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(ao);
  if (any(greaterThanEqual(texel, size))) return;
  float z = linear_depth(texelFetch(gbuffer_depth, texel, 0).r);
  float sum = 0.0, weight = 0.0;
  for (int y = -2; y <= 2; ++y)
    for (int x = -2; x <= 2; ++x) {
      ivec2 q = clamp(texel + ivec2(x, y), ivec2(0), size - 1);
      float zq = linear_depth(texelFetch(gbuffer_depth, q, 0).r);
      float w = abs(zq - z) <= 0.05 * z ? 1.0 : 0.0;
      sum += w * texelFetch(noisy, q, 0).r;
      weight += w;
    }
  imageStore(ao, texel, vec4(weight > 0.0 ? sum / weight : 1.0));
}
