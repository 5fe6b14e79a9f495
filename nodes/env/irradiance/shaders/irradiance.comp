#version 460
#extension GL_GOOGLE_include_directive : require
// env.irradiance: for each output texel's normal n, irradiance / pi by direct cosine
// convolution over every texel of one environment mip, sum L max(n.l, 0) dw / pi with exact
// texel solid angles. Non-finite texels count as 0.
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray env;  // the six faces of the mip integrated over
layout(binding = 1, rgba16f) uniform writeonly image2DArray irradiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(irradiance).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec3 n = cube_direction(face, (vec2(texel) + 0.5) / float(size));
  int env_size = textureSize(env, 0).x;
  vec3 sum = vec3(0.0);
  for (int f = 0; f < 6; ++f)
    for (int j = 0; j < env_size; ++j)
      for (int i = 0; i < env_size; ++i) {
        vec3 l = cube_direction(f, (vec2(i, j) + 0.5) / float(env_size));
        float n_dot_l = dot(n, l);
        if (n_dot_l <= 0.0) continue;
        vec3 radiance = texelFetch(env, ivec3(i, j, f), 0).rgb;
        if (any(isnan(radiance)) || any(isinf(radiance))) continue;
        sum += radiance * (n_dot_l * cube_texel_solid_angle(ivec2(i, j), env_size));
      }
  imageStore(irradiance, ivec3(texel, face), vec4(sum / 3.14159265358979, 1.0));
}
