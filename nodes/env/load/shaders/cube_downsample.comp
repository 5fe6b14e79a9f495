#version 460
#extension GL_GOOGLE_include_directive : require
// env.load, mips 1 and up: each texel the solid-angle-weighted mean of the finer mip's texels it
// covers (2x2, or 2x3 and 3x3 at the last row and column of an odd size), so every mip holds
// the same integral of radiance.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray finer;  // the mip above, in GENERAL
layout(binding = 1, rgba16f) uniform writeonly image2DArray cube_mip;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(cube_mip).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  int fine = textureSize(finer, 0).x;
  ivec2 lo = 2 * texel;
  ivec2 hi = min(mix(lo + 1, ivec2(fine - 1), equal(texel, ivec2(size - 1))), ivec2(fine - 1));
  vec3 sum = vec3(0.0);
  float area = 0.0;
  for (int j = lo.y; j <= hi.y; ++j)
    for (int i = lo.x; i <= hi.x; ++i) {
      float w = cube_texel_solid_angle(ivec2(i, j), fine);
      sum += w * texelFetch(finer, ivec3(i, j, face), 0).rgb;
      area += w;
    }
  imageStore(cube_mip, ivec3(texel, face), vec4(sum / area, 1.0));
}
