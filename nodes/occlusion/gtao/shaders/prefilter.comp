#version 460
#extension GL_GOOGLE_include_directive : require
// Device depth on the horizon grid and its averaged mips, five levels in one dispatch: each
// invocation copies a 2x2 quad of grid texels and averages it into mip 1 in registers, then each
// 8x8 workgroup (a 16x16 tile) reduces its mip-1 texels through shared memory. A quad per
// invocation rather than a texel, and one barrier per level into alternating arrays, because
// lavapipe pays for every invocation and every barrier: this cut the pass from 37 to 17 ms at
// 1280x720 (lumagraph-bench-ao).
// Mip 0 is the grid's own (resolution_scale 1/k): texel i is the G-buffer's depth at grid_pixel(i),
// the pixel the horizon search runs at, so a texel's depth and its position are an exact point
// of the surface; below resolution_scale 1 the chain costs 1/k^2 of the full-resolution one.
// Reversed-Z device depth is near / linear depth, which is affine across the screen on any
// plane, so a block's average is the plane's value at the mean of its points and bilinear taps
// between mip texels are exact on planes: far horizon samples read coarse mips without biasing
// flat surfaces toward occlusion.
#include "nodes/occlusion/gtao/shaders/gtao_constants.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 1) uniform sampler2D device_depth;  // the G-buffer's
layout(binding = 2, r32f) uniform writeonly image2D mip0;
layout(binding = 3, r32f) uniform writeonly image2D mip1;
layout(binding = 4, r32f) uniform writeonly image2D mip2;
layout(binding = 5, r32f) uniform writeonly image2D mip3;
layout(binding = 6, r32f) uniform writeonly image2D mip4;

shared float tiles[2][8][8];  // mip 1, 3 in [0]; mip 2 in [1] (levels alternate, one barrier each)

// The mean of the values that are not negative (negative: beyond the image), or -1 if none is.
float average_valid(vec4 q) {
  vec4 valid = vec4(greaterThanEqual(q, vec4(0.0)));
  float count = dot(valid, vec4(1.0));
  return count > 0.0 ? dot(q * valid, vec4(1.0)) / count : -1.0;
}

float copy_texel(ivec2 texel, ivec2 size) {
  if (any(greaterThanEqual(texel, size))) return -1.0;  // left out of the averages
  float d = texelFetch(device_depth, grid_pixel(texel), 0).r;
  imageStore(mip0, texel, vec4(d));
  return d;
}

void store(int level, ivec2 texel, float d) {
  if (level == 2 && all(lessThan(texel, imageSize(mip2)))) imageStore(mip2, texel, vec4(d));
  if (level == 3 && all(lessThan(texel, imageSize(mip3)))) imageStore(mip3, texel, vec4(d));
  if (level == 4 && all(lessThan(texel, imageSize(mip4)))) imageStore(mip4, texel, vec4(d));
}

void main() {
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  ivec2 quad = ivec2(gl_GlobalInvocationID.xy);  // this invocation's mip-1 texel
  ivec2 size = imageSize(mip0);
  ivec2 texel = quad * 2;
  float m = average_valid(vec4(copy_texel(texel, size), copy_texel(texel + ivec2(1, 0), size),
                               copy_texel(texel + ivec2(0, 1), size), copy_texel(texel + ivec2(1, 1), size)));
  if (all(lessThan(quad, imageSize(mip1)))) imageStore(mip1, quad, vec4(m));
  tiles[0][local.y][local.x] = m;
  for (int level = 2; level <= 4; ++level) {
    barrier();
    int stride = 1 << (level - 1);  // in mip-1 texels
    if (all(equal(local % stride, ivec2(0)))) {
      int from = level % 2, h = stride / 2;
      m = average_valid(vec4(tiles[from][local.y][local.x], tiles[from][local.y][local.x + h],
                             tiles[from][local.y + h][local.x], tiles[from][local.y + h][local.x + h]));
      tiles[1 - from][local.y][local.x] = m;
      store(level, quad >> (level - 1), m);
    }
  }
}
