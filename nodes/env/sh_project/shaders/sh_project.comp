#version 460
#extension GL_GOOGLE_include_directive : require
// Pass 1 of env.sh_project: each workgroup projects one block of kBlockTexels texels of one face
// (row-major, the last block of a face may be short) onto real SH and writes its sums to
// `partials`; sh_reduce.comp adds the blocks up. A texel contributes L times the integral of
// Y_lm over the texel: the exact solid angle times the Jacobian-weighted mean of Y_lm at 2x2
// Gauss points (the centre alone leaves band 4 of a constant sky at 5e-4 on 32^2 faces).
// Each invocation sums kBlockTexels / 32 texels in registers and the block's 32 lanes are added
// once: on lavapipe every barrier costs a pass over the workgroup, and a tree per coefficient
// (9 barriers each, 25 coefficients) cost most of the time. 64 texels an invocation stay well
// inside lavapipe's 65535 loop iterations an invocation (about 110 a texel); 32 lanes keep the
// lanes' sums in 9.6 KB of shared memory (Vulkan guarantees 16 KB). Only the coefficients up to
// the order are summed. Non-finite texels count as 0 and are counted.
#include "nodes/env/common/shaders/cube_map.glsl"
#include "nodes/env/common/shaders/sh_basis.glsl"

const uint kLanes = 32u;
const uint kBlockTexels = 64u * kLanes;  // sh_project_kernel.cpp's kBlockTexels
layout(local_size_x = 32) in;

layout(binding = 0) uniform sampler2DArray env;  // the six faces of the mip projected
// Per block, LG_SH_MAX_COUNT sums; the first's w holds the block's number of non-finite texels.
layout(std430, binding = 1) writeonly buffer Partials { vec4 partials[]; };
// (order + 1)^2 coefficients summed; a specialization constant, so the loops over coefficients
// unroll and their arrays stay in registers (as a push constant they were indexed in memory,
// and the basis was evaluated in full).
layout(constant_id = 0) const int count = 9;

shared vec3 lane_sums[kLanes * uint(LG_SH_MAX_COUNT)];
shared uint lane_non_finite[kLanes];

void main() {
  const uint lane = gl_LocalInvocationIndex;
  const int size = textureSize(env, 0).x;
  const int face = int(gl_WorkGroupID.y);
  const uint face_texels = uint(size * size);
  const uint first = gl_WorkGroupID.x * kBlockTexels;
  vec3 sums[LG_SH_MAX_COUNT];
  for (int k = 0; k < count; ++k) sums[k] = vec3(0.0);
  uint non_finite = 0u;
  for (uint i = first + lane; i < min(first + kBlockTexels, face_texels); i += kLanes) {
    const ivec2 texel = ivec2(int(i % uint(size)), int(i / uint(size)));
    vec3 radiance = texelFetch(env, ivec3(texel, face), 0).rgb;
    if (any(isnan(radiance)) || any(isinf(radiance))) {
      radiance = vec3(0.0);
      ++non_finite;
    }
    float y_texel[LG_SH_MAX_COUNT];
    for (int k = 0; k < count; ++k) y_texel[k] = 0.0;
    float jacobian_sum = 0.0;
    for (int g = 0; g < 4; ++g) {
      const vec2 gauss = vec2(g & 1, g >> 1) * (1.0 / sqrt(3.0)) + (0.5 - 0.5 / sqrt(3.0));  // 0.5 -+ 0.5 / sqrt(3)
      const vec2 uv = (vec2(texel) + gauss) / float(size);
      const float jacobian = cube_jacobian(uv * 2.0 - 1.0);
      float y[LG_SH_MAX_COUNT];
      sh_evaluate(cube_direction(face, uv), y);
      for (int k = 0; k < count; ++k) y_texel[k] += jacobian * y[k];
      jacobian_sum += jacobian;
    }
    radiance *= cube_texel_solid_angle(texel, size) / jacobian_sum;
    for (int k = 0; k < count; ++k) sums[k] += radiance * y_texel[k];
  }
  for (int k = 0; k < count; ++k) lane_sums[lane * uint(LG_SH_MAX_COUNT) + uint(k)] = sums[k];
  lane_non_finite[lane] = non_finite;
  barrier();
  if (lane < uint(count)) {
    vec3 sum = vec3(0.0);
    uint bad = 0u;
    for (uint l = 0u; l < kLanes; ++l) {
      sum += lane_sums[l * uint(LG_SH_MAX_COUNT) + lane];
      bad += lane_non_finite[l];
    }
    const uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    partials[block * uint(LG_SH_MAX_COUNT) + lane] = vec4(sum, lane == 0u ? float(bad) : 0.0);
  }
}
