#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's further bounces (its `bounces` param above 1), one invocation per voxel of level 0:
// the irradiance the voxel's surface gets from the light the chain holds (the direct light and
// the bounces so far), by the six cones of the pixels' diffuse light (voxel_trace.glsl: every
// level, a sample's width a step) from one voxel out along its mean normal, E = pi sum w_i L_i.
// Written as float bits into the voxel's last three ints of the voxelization's sums
// (voxel_common.glsl) for the next injection (voxel_inject.comp), which adds albedo x E / pi to
// the voxel's direct light: one more bounce each time, a Jacobi step of the rendering equation
// over the voxels. The sky the cones leave open is not gathered: the voxel's own sky light is
// injected by its visibility (voxel_sky.comp).
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/gi/voxel/shaders/voxel_trace.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) buffer Grid { int grid[]; };

void main() {
  ivec3 c = voxel_invocation_cell(voxel.counts.xyz);
  if (any(greaterThanEqual(c, voxel.counts.xyz))) return;
  uint base = LG_VOXEL_INTS * voxel_index(c);
  vec3 n = voxel_surface_normal(grid[base + 6u], ivec3(grid[base + 3u], grid[base + 4u], grid[base + 5u]));
  if (n == vec3(0.0)) return;
  float cell = voxel.origin_cell.w;
  vec3 origin = voxel.origin_cell.xyz + (vec3(c) + 0.5) * cell + n * cell;
  vec3 light = vec3(0.0);
  for (int i = 0; i < kHemisphereCones; ++i)
    light += hemisphere_cone_weight(i) * trace_hemisphere_cone(origin, n, i, 0.0, kAllLevels, 1.0).light;
  vec3 e = clamp(finite_or_zero(LG_PI * light), 0.0, 65504.0);
  grid[base + 11u] = floatBitsToInt(e.r);
  grid[base + 12u] = floatBitsToInt(e.g);
  grid[base + 13u] = floatBitsToInt(e.b);
}
