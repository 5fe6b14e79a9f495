#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 2 of env.irradiance: for each output texel's normal n, irradiance / pi by direct cosine
// convolution over every texel of one environment mip, sum L max(n.l, 0) dw / pi, reading the
// texels as irradiance_sources.comp left them (direction, radiance x exact solid angle). No
// branch in the loop: lavapipe would run both sides.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray sources;
layout(binding = 1, rgba16f) uniform writeonly image2DArray irradiance;

// Each invocation sums a kBlock x kBlock block of output texels, so each light read serves
// kBlock^2 normals (lavapipe: the reads cost more than the arithmetic).
const int kBlock = 4;  // irradiance_kernel.cpp's kOutputBlock
const int kNormals = kBlock * kBlock;

void main() {
  const ivec2 base = kBlock * ivec2(gl_GlobalInvocationID.xy);
  const int face = int(gl_GlobalInvocationID.z);
  const int size = imageSize(irradiance).x;
  if (any(greaterThanEqual(base, ivec2(size)))) return;
  vec3 n[kNormals], sum[kNormals];
  for (int q = 0; q < kNormals; ++q) {
    n[q] = cube_direction(face, (vec2(base + ivec2(q % kBlock, q / kBlock)) + 0.5) / float(size));
    sum[q] = vec3(0.0);
  }
  const int source_size = textureSize(sources, 0).y;
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < source_size; ++j)
      for (int i = 0; i < source_size; ++i) {
        const vec3 l = texelFetch(sources, ivec3(2 * i, j, f), 0).xyz;
        const vec3 light = texelFetch(sources, ivec3(2 * i + 1, j, f), 0).rgb;
        for (int q = 0; q < kNormals; ++q) sum[q] += light * max(dot(n[q], l), 0.0);
      }
  for (int q = 0; q < kNormals; ++q) {
    const ivec2 texel = base + ivec2(q % kBlock, q / kBlock);
    if (all(lessThan(texel, ivec2(size)))) imageStore(irradiance, ivec3(texel, face), vec4(sum[q] / 3.14159265358979, 1.0));
  }
}
