#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's mip chain, anisotropic (six directions), one invocation per voxel of the level being
// made. For a ray travelling along +x (and so for each of the six axis directions) the voxel's
// colour and opacity are its children's composited front to back along x, pair by pair (the front
// child's colour plus the back one's seen through it), then averaged over the four pairs across x:
// colour premultiplied by opacity. A lit roof's top voxels then stay hidden behind its dark lower
// ones from below, where an isotropic mean let a thin roof or wall glow on its dark side (in the
// layout of voxel_common.glsl). The counts are powers of two (cell_grid.h), so a child's index is
// 2i or 2i + 1, clamped where a side is already one voxel.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image3D finer_x;  // level - 1
layout(binding = 2, rgba16f) uniform readonly image3D finer_y;
layout(binding = 3, rgba16f) uniform readonly image3D finer_z;
layout(binding = 4, rgba16f) uniform writeonly image3D coarser_x;  // level
layout(binding = 5, rgba16f) uniform writeonly image3D coarser_y;
layout(binding = 6, rgba16f) uniform writeonly image3D coarser_z;
layout(std430, binding = 7) readonly buffer Grid { int grid[]; };  // the voxelization's sums
layout(push_constant) uniform Push {
  int level;   // the one being made, 1 or more
  int facing;  // 1: the param facing_colour (facing_only)
};

// With facing_colour, child k of level 0 as a ray travelling the positive (negative = 0) or
// negative way along `axis` sees it inside a coarser voxel: opaque as it is, but its colour only
// where its surface faces the ray (its normal's component along the axis against the travel). A
// sunlit roof's top then shows rays travelling sideways nothing (they meet its edge), where in a
// coarse voxel averaged beside its dark underside it lit the rooms below (the closed room in
// tests/gi/voxel_gpu_test.cpp: 1.8% of the roof's light inside without it, 0.00% with). The price:
// a surface seen obliquely lends coarse levels only the share of the faces that see it (the wall
// in that test: -32%). Level 0 stays isotropic: a cone reading it meets the nearest surface first.
vec4 facing_only(vec4 v, ivec3 k, int axis, int negative) {
  if (level != 1 || facing == 0) return v;
  int n = grid[LG_VOXEL_INTS * voxel_index(k) + 3u + uint(axis)];
  return (negative == 1 ? n > 0 : n < 0) ? v : vec4(0.0, 0.0, 0.0, v.a);
}

vec4 over(vec4 front, vec4 back) {
  return front + (1.0 - front.a) * back;
}

// Both directions along `axis` (0, 1, 2): the four pairs of children of voxel c, each composited
// front to back (a side of one voxel has a single child), averaged.
#define LG_COMPOSITE_AXIS(axis, finer, coarser)                                                   \
  {                                                                                               \
    ivec3 along = ivec3(0), across_a = ivec3(0), across_b = ivec3(0);                            \
    along[axis] = 1;                                                                              \
    across_a[(axis + 1) % 3] = 1;                                                                 \
    across_b[(axis + 2) % 3] = 1;                                                                 \
    bool paired = 2 * c[axis] + 1 <= last[axis];                                                  \
    vec4 positive = vec4(0.0), negative = vec4(0.0);                                              \
    for (int j = 0; j < 2; ++j)                                                                   \
      for (int i = 0; i < 2; ++i) {                                                               \
        ivec3 low = min(2 * c + i * across_a + j * across_b, last);                               \
        vec4 low_p = facing_only(imageLoad(finer, voxel_chain_texel(low, finer_counts, 0)), low, axis, 0); \
        vec4 low_n = facing_only(imageLoad(finer, voxel_chain_texel(low, finer_counts, 1)), low, axis, 1); \
        vec4 high_p = facing_only(imageLoad(finer, voxel_chain_texel(low + along, finer_counts, 0)), low + along, axis, 0); \
        vec4 high_n = facing_only(imageLoad(finer, voxel_chain_texel(low + along, finer_counts, 1)), low + along, axis, 1); \
        positive += paired ? over(low_p, high_p) : low_p;                                         \
        negative += paired ? over(high_n, low_n) : low_n;                                         \
      }                                                                                           \
    imageStore(coarser, voxel_chain_texel(c, counts, 0), positive * 0.25);                        \
    imageStore(coarser, voxel_chain_texel(c, counts, 1), negative * 0.25);                        \
  }

void main() {
  ivec3 counts = voxel_level_counts(level), finer_counts = voxel_level_counts(level - 1);
  ivec3 c = voxel_invocation_cell(counts);
  if (any(greaterThanEqual(c, counts))) return;
  ivec3 last = finer_counts - 1;
  LG_COMPOSITE_AXIS(0, finer_x, coarser_x)
  LG_COMPOSITE_AXIS(1, finer_y, coarser_y)
  LG_COMPOSITE_AXIS(2, finer_z, coarser_z)
}
