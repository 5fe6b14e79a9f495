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

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(irradiance).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec3 n = cube_direction(face, (vec2(texel) + 0.5) / float(size));
  int source_size = textureSize(sources, 0).y;
  vec3 sum = vec3(0.0);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < source_size; ++j)
      for (int i = 0; i < source_size; ++i) {
        const vec3 l = texelFetch(sources, ivec3(2 * i, j, f), 0).xyz;
        sum += texelFetch(sources, ivec3(2 * i + 1, j, f), 0).rgb * max(dot(n, l), 0.0);
      }
  imageStore(irradiance, ivec3(texel, face), vec4(sum / 3.14159265358979, 1.0));
}
