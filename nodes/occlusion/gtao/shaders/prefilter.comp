#version 460
#extension GL_GOOGLE_include_directive : require
// Device depth and its averaged mips, five levels in one dispatch: each 16x16 workgroup reduces
// its tile through shared memory. Reversed-Z device depth is near / linear depth, which is
// affine across the screen on any plane, so a block's average is the plane's value at the
// block's centre and bilinear taps between mip texels are exact on planes: far horizon samples
// read coarse mips without biasing flat surfaces toward occlusion.
#include "nodes/occlusion/gtao/shaders/gtao_constants.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 1) uniform sampler2D device_depth;
layout(binding = 2, r32f) uniform writeonly image2D mip0;
layout(binding = 3, r32f) uniform writeonly image2D mip1;
layout(binding = 4, r32f) uniform writeonly image2D mip2;
layout(binding = 5, r32f) uniform writeonly image2D mip3;
layout(binding = 6, r32f) uniform writeonly image2D mip4;

shared float tile[16][16];

void store(int level, ivec2 texel, float d) {
  if (level == 1 && all(lessThan(texel, imageSize(mip1)))) imageStore(mip1, texel, vec4(d));
  if (level == 2 && all(lessThan(texel, imageSize(mip2)))) imageStore(mip2, texel, vec4(d));
  if (level == 3 && all(lessThan(texel, imageSize(mip3)))) imageStore(mip3, texel, vec4(d));
  if (level == 4 && all(lessThan(texel, imageSize(mip4)))) imageStore(mip4, texel, vec4(d));
}

void main() {
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(device_depth, 0);
  float d = -1.0;  // beyond the image: left out of the averages
  if (all(lessThan(texel, size))) {
    d = texelFetch(device_depth, texel, 0).r;
    imageStore(mip0, texel, vec4(d));
  }
  tile[local.y][local.x] = d;
  for (int level = 1; level <= 4; ++level) {
    barrier();
    int stride = 1 << level;
    bool reducing = all(equal(local % stride, ivec2(0)));
    float m = -1.0;
    if (reducing) {
      int half_stride = stride / 2;
      vec4 q = vec4(tile[local.y][local.x], tile[local.y][local.x + half_stride], tile[local.y + half_stride][local.x],
                    tile[local.y + half_stride][local.x + half_stride]);
      vec4 valid = vec4(greaterThanEqual(q, vec4(0.0)));
      float count = dot(valid, vec4(1.0));
      if (count > 0.0) m = dot(q * valid, vec4(1.0)) / count;
    }
    barrier();
    if (reducing) {
      tile[local.y][local.x] = m;
      store(level, texel >> level, m);
    }
  }
}
