#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's mip chain, one invocation per voxel of the level being made: the mean of the (up to)
// eight voxels below it, colour premultiplied by opacity, so that a level's colour is the light
// its box sends out on average and its opacity the fraction of it that is filled (isotropic: the
// same in every direction). The counts are powers of two (cell_grid.h), so a child's index is 2i
// or 2i + 1, clamped where a side is already one voxel.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image3D finer;
layout(binding = 2, rgba16f) uniform writeonly image3D coarser;

void main() {
  ivec3 size = imageSize(coarser);
  ivec3 c = voxel_invocation_cell(size);
  if (any(greaterThanEqual(c, size))) return;
  ivec3 last = imageSize(finer) - 1;
  vec4 sum = vec4(0.0);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) sum += imageLoad(finer, min(2 * c + ivec3(x, y, z), last));
  imageStore(coarser, c, sum * 0.125);
}
