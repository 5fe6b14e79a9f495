#version 460
#extension GL_GOOGLE_include_directive : require
// The log2-luminance histogram: each workgroup counts a tile of 64x64 pixels (4x4 per
// invocation, a pixel's neighbours 16 apart so that reads stay together) in shared memory, then
// adds its non-empty bins to the global histogram (cleared by the kernel before this pass).
// Pixels with a NaN or infinite channel are not counted.
#include "nodes/post/exposure/shaders/exposure_common.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1, std430) buffer Histogram { uint counts[]; };

shared uint local_counts[kBins];

void main() {
  local_counts[gl_LocalInvocationIndex] = 0u;  // 256 invocations, one per bin
  barrier();
  ivec2 size = textureSize(scene_color, 0);
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * 64 + ivec2(gl_LocalInvocationID.xy);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      ivec2 texel = origin + 16 * ivec2(i, j);
      if (any(greaterThanEqual(texel, size))) continue;
      vec3 c = texelFetch(scene_color, texel, 0).rgb;
      if (!any(isnan(c)) && !any(isinf(c))) atomicAdd(local_counts[luminance_bin(luminance(c))], 1u);
    }
  barrier();
  uint count = local_counts[gl_LocalInvocationIndex];
  if (count > 0u) atomicAdd(counts[gl_LocalInvocationIndex], count);
}
