#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1 of env.sh_project: each workgroup projects one 16x16 tile of one face onto real SH
// (bands <= 4) and writes its sums to `partials`; sh_reduce.comp adds the tiles up. A texel
// contributes L times the integral of Y_lm over the texel: the exact solid angle times the
// Jacobian-weighted mean of Y_lm at 2x2 Gauss points (the centre alone leaves band 4 of a
// constant sky at 5e-4 on 32^2 faces). One texel per invocation because lavapipe ends an
// invocation's loops after 65535 iterations in all. Non-finite texels count as 0 and are counted.
#include "nodes/env/common/shaders/cube_map.glsl"
#include "nodes/env/common/shaders/sh_basis.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2DArray env;  // the six faces of the mip projected
// Per tile, LG_SH_MAX_COUNT sums; the first's w holds the tile's number of non-finite texels.
layout(std430, binding = 1) writeonly buffer Partials { vec4 partials[]; };

shared vec3 lanes[256];
shared uint non_finite;

void main() {
  uint lane = gl_LocalInvocationIndex;
  if (lane == 0u) non_finite = 0u;
  int size = textureSize(env, 0).x;
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_WorkGroupID.z);
  float y_texel[LG_SH_MAX_COUNT];
  for (int k = 0; k < LG_SH_MAX_COUNT; ++k) y_texel[k] = 0.0;
  vec3 radiance = vec3(0.0);
  bool bad = false;
  if (all(lessThan(texel, ivec2(size)))) {
    radiance = texelFetch(env, ivec3(texel, face), 0).rgb;
    bad = any(isnan(radiance)) || any(isinf(radiance));
    if (bad) radiance = vec3(0.0);
    float jacobian_sum = 0.0;
    for (int g = 0; g < 4; ++g) {
      vec2 gauss = vec2(g & 1, g >> 1) * (1.0 / sqrt(3.0)) + (0.5 - 0.5 / sqrt(3.0));  // 0.5 -+ 0.5 / sqrt(3)
      vec2 uv = (vec2(texel) + gauss) / float(size);
      float jacobian = cube_jacobian(uv * 2.0 - 1.0);
      float y[LG_SH_MAX_COUNT];
      sh_evaluate(cube_direction(face, uv), y);
      for (int k = 0; k < LG_SH_MAX_COUNT; ++k) y_texel[k] += jacobian * y[k];
      jacobian_sum += jacobian;
    }
    radiance *= cube_texel_solid_angle(texel, size) / jacobian_sum;
  }
  barrier();
  if (bad) atomicAdd(non_finite, 1u);
  uint tile = (gl_WorkGroupID.z * gl_NumWorkGroups.y + gl_WorkGroupID.y) * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  for (int k = 0; k < LG_SH_MAX_COUNT; ++k) {
    lanes[lane] = radiance * y_texel[k];
    barrier();
    for (uint half_size = 128u; half_size > 0u; half_size /= 2u) {
      if (lane < half_size) lanes[lane] += lanes[lane + half_size];
      barrier();
    }
    if (lane == 0u) partials[tile * uint(LG_SH_MAX_COUNT) + uint(k)] = vec4(lanes[0], k == 0 ? float(non_finite) : 0.0);
    barrier();
  }
}
