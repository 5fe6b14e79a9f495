#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's optional volume output (a debug view: `render --dump`, the inspector), one mip of it
// a dispatch, one invocation per texel: voxel c of chain level `level` (voxel_common.glsl's
// layout) as rgb the radiance of its lit surfaces, W/m^2/sr, over the six ray directions (their
// colours premultiplied by facing, summed, over the summed facing, as voxel_cones.comp divides
// one direction's), and a: its opacity averaged over the three axes. Texels past the chain's
// counts (shorter sides of the grid, levels the chain lacks) are 0.
#include "nodes/gi/voxel/shaders/voxel_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler3D seen_x;  // the chain, texelFetch only
layout(binding = 2) uniform sampler3D seen_y;
layout(binding = 3) uniform sampler3D seen_z;
layout(binding = 4) uniform sampler3D opacity_image;
layout(binding = 5, rgba16f) uniform writeonly image3D volume;  // the output's mip `level`
layout(push_constant) uniform Push {
  int level;
};

void main() {
  ivec3 size = imageSize(volume);
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  ivec3 c = ivec3(id.x, id.y % size.y, id.y / size.y);
  if (any(greaterThanEqual(c, size))) return;
  ivec3 counts = voxel_level_counts(level);
  if (level >= voxel.counts.w || any(greaterThanEqual(c, counts))) {
    imageStore(volume, c, vec4(0.0));
    return;
  }
  vec4 colour = vec4(0.0);  // rgb premultiplied, a: facing
  for (int negative = 0; negative < 2; ++negative) {
    ivec3 t = voxel_chain_texel(c, counts, negative);
    colour += texelFetch(seen_x, t, level) + texelFetch(seen_y, t, level) + texelFetch(seen_z, t, level);
  }
  vec3 opacity = texelFetch(opacity_image, voxel_chain_texel(c, counts, 0), level).rgb;
  // Below 1e-3 of a voxel facing any ray the colour (at most as large) is negligible.
  imageStore(volume, c, vec4(colour.rgb / max(colour.a, 1e-3), (opacity.x + opacity.y + opacity.z) / 3.0));
}
