#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's mip chain, anisotropic (six directions), one invocation per voxel of the level being
// made. For a ray travelling along +x (and so for each of the six axis directions) the voxel's
// colour, facing and opacity are its children's composited front to back along x, pair by pair
// (the front child's plus the back one's seen through it), then averaged over the four pairs
// across x: colour and facing premultiplied by opacity. A lit roof's top voxels then stay hidden
// behind its dark lower ones from below, where an isotropic mean let a thin roof or wall glow on
// its dark side; sideways, where compositing cannot tell above from below, the roof's top shows
// no colour because it faces no ray travelling sideways (voxel_inject.comp). In the layout of
// voxel_common.glsl. The counts are powers of two (cell_grid.h), so a child's index is 2i or
// 2i + 1, clamped where a side is already one voxel.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1, rgba16f) uniform readonly image3D finer_x;  // level - 1
layout(binding = 2, rgba16f) uniform readonly image3D finer_y;
layout(binding = 3, rgba16f) uniform readonly image3D finer_z;
layout(binding = 4, rgba16f) uniform writeonly image3D coarser_x;  // level
layout(binding = 5, rgba16f) uniform writeonly image3D coarser_y;
layout(binding = 6, rgba16f) uniform writeonly image3D coarser_z;
layout(binding = 7, rgba16f) uniform readonly image3D finer_opacity;
layout(binding = 8, rgba16f) uniform writeonly image3D coarser_opacity;
layout(push_constant) uniform Push {
  int level;  // the one being made, 1 or more
};

// Colour and facing, and opacity along the same axis, as a ray travelling along `axis` the
// positive (negative = 0) or negative way sees child k of the finer level.
struct Seen {
  vec4 colour;  // rgb premultiplied, a: facing
  float opacity;
};

// (A macro: images of a declared format cannot be passed to functions.)
#define LG_CHILD(finer, k, axis, negative) \
  Seen(imageLoad(finer, voxel_chain_texel(k, finer_counts, negative)), \
       imageLoad(finer_opacity, voxel_chain_texel(k, finer_counts, negative))[axis])

Seen over(Seen front, Seen back) {
  float through = 1.0 - front.opacity;
  return Seen(front.colour + through * back.colour, front.opacity + through * back.opacity);
}

// Both directions along `axis` (0, 1, 2): the four pairs of children of voxel c, each composited
// front to back (a side of one voxel has a single child), averaged; opacity into the axis's
// component of o_positive and o_negative (equal: compositing two opacities is the same either
// way round, 1 - (1 - a)(1 - b)).
#define LG_COMPOSITE_AXIS(axis, finer, coarser)                                              \
  {                                                                                          \
    ivec3 along = ivec3(0), across_a = ivec3(0), across_b = ivec3(0);                       \
    along[axis] = 1;                                                                         \
    across_a[(axis + 1) % 3] = 1;                                                            \
    across_b[(axis + 2) % 3] = 1;                                                            \
    bool paired = 2 * c[axis] + 1 <= last[axis];                                             \
    Seen positive = Seen(vec4(0.0), 0.0), negative = Seen(vec4(0.0), 0.0);                   \
    for (int j = 0; j < 2; ++j)                                                              \
      for (int i = 0; i < 2; ++i) {                                                          \
        ivec3 low = min(2 * c + i * across_a + j * across_b, last);                          \
        Seen low_p = LG_CHILD(finer, low, axis, 0), low_n = LG_CHILD(finer, low, axis, 1);         \
        Seen p = low_p, n = low_n;                                                           \
        if (paired) {                                                                        \
          p = over(low_p, LG_CHILD(finer, low + along, axis, 0));                               \
          n = over(LG_CHILD(finer, low + along, axis, 1), low_n);                               \
        }                                                                                    \
        positive.colour += p.colour, positive.opacity += p.opacity;                          \
        negative.colour += n.colour, negative.opacity += n.opacity;                          \
      }                                                                                      \
    imageStore(coarser, voxel_chain_texel(c, counts, 0), positive.colour * 0.25);            \
    imageStore(coarser, voxel_chain_texel(c, counts, 1), negative.colour * 0.25);            \
    o_positive[axis] = positive.opacity * 0.25;                                              \
    o_negative[axis] = negative.opacity * 0.25;                                              \
  }

void main() {
  ivec3 counts = voxel_level_counts(level), finer_counts = voxel_level_counts(level - 1);
  ivec3 c = voxel_invocation_cell(counts);
  if (any(greaterThanEqual(c, counts))) return;
  ivec3 last = finer_counts - 1;
  vec3 o_positive, o_negative;
  LG_COMPOSITE_AXIS(0, finer_x, coarser_x)
  LG_COMPOSITE_AXIS(1, finer_y, coarser_y)
  LG_COMPOSITE_AXIS(2, finer_z, coarser_z)
  // The opacity image's alpha is unused.
  imageStore(coarser_opacity, voxel_chain_texel(c, counts, 0), vec4(o_positive, 1.0));
  imageStore(coarser_opacity, voxel_chain_texel(c, counts, 1), vec4(o_negative, 1.0));
}
