#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's sky visibility, one invocation per voxel of level 0, with the environment's SH
// linked: how much of the sky the surface in the voxel sees, from the voxels' own opacity. The six
// cones of the pixels' diffuse light (voxel_trace.glsl) start one voxel out along the voxel's mean
// normal and march the chain, counting every voxel's opacity whichever way it faces, all the way
// out of the grid; the visibility is 1 - sum w_i occluded_i (cosine-weighted, so an open floor
// reads 1 and the inside of a closed room 0), occluded_i the larger of the cone's two opacities.
// Written into the voxel's eighth int of the voxelization's sums (its sky visibility, as float
// bits; voxel_common.glsl) for the second injection (voxel_inject.comp), which adds the sky's
// light: albedo x E_sky(n) x visibility / pi.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"
#include "nodes/gi/voxel/shaders/voxel_trace.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) buffer Grid { int grid[]; };

const float kWholeGrid = 1e30;  // occlusion counted all the way out of the grid
// Levels up to voxel_ray_level() (voxel_common.glsl: 0 at resolution 64), a voxel of it a step at
// most (at most 128 steps, voxel_trace.glsl): with every level a cone crossing a ceiling took one
// partly opaque sample of it and left the grid, so a closed room's inside faces saw part of the
// sky (VoxelGpu test at 32: 2.9% of the sky's light inside with every level, 1.1% with levels
// 0-1, 0.3% with level 0). Paid only when the volume is rebuilt.
// Half-voxel steps: at one-voxel steps the filter spread a slab's face over two samples of partial
// opacity, and the sky's light inside a closed room, gathered by the pixels' cones capped by this
// visibility (voxel_cones.comp), was 1.0% of the sky's (VoxelGpu test at 32); with half steps 0.70%.
const float kSkyStep = 0.5;

void main() {
  ivec3 c = voxel_invocation_cell(voxel.counts.xyz);
  if (any(greaterThanEqual(c, voxel.counts.xyz))) return;
  uint base = LG_VOXEL_INTS * voxel_index(c);
  int triangles = grid[base + 6u];
  if (triangles <= 0) return;
  vec3 n = voxel_surface_normal(triangles, ivec3(grid[base + 3u], grid[base + 4u], grid[base + 5u]));
  // No visibility for a voxel whose normals cancel: -1 tells the cones (voxel_cones.comp) so.
  if (n == vec3(0.0)) {
    grid[base + 7u] = floatBitsToInt(-1.0);
    return;
  }
  float cell = voxel.origin_cell.w;
  vec3 origin = voxel.origin_cell.xyz + (vec3(c) + 0.5) * cell + n * cell;
  float occluded = 0.0;
  for (int i = 0; i < kHemisphereCones; ++i) {
    // A cone stops once what faces it is 99% opaque, where the opacity counted whichever way
    // may still be lower: both are what hides the sky.
    Cone cone = trace_hemisphere_cone(origin, n, i, kWholeGrid, voxel_ray_level(), kSkyStep);
    occluded += hemisphere_cone_weight(i) * max(cone.occluded, cone.opacity);
  }
  grid[base + 7u] = floatBitsToInt(clamp(1.0 - occluded, 0.0, 1.0));
}
