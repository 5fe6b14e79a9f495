// An upsample at resolution_scale 1/k below 1, included by a shader that defines the target's
// format (LG_UPSAMPLE_FORMAT) and what the sky gets (LG_UPSAMPLE_SKY): one invocation per texel
// of the smaller image writes that texel's block of G-buffer pixels, each blended from the 2 x 2
// texels around it guided by depth and normals (joint_upsample.glsl).
#ifndef LG_UPSAMPLE_PASS_GLSL
#define LG_UPSAMPLE_PASS_GLSL

#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D low_tex;
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3, LG_UPSAMPLE_FORMAT) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over low_tex's
};

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(low_tex, 0), full_size = imageSize(result);
  if (any(greaterThanEqual(low, low_size))) return;
  UpsampleTaps taps = upsample_taps(low_tex, depth_tex, normal_tex, low, k);
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  for (int y = low.y * k; y < end.y; ++y)
    for (int x = low.x * k; x < end.x; ++x) {
      ivec2 texel = ivec2(x, y);
      float depth = texelFetch(depth_tex, texel, 0).r;
      vec3 n = decode_normal_unnormalized(texelFetch(normal_tex, texel, 0).rgb);
      vec2 f = upsample_fraction(texel, low, k);
      imageStore(result, texel, depth > 0.0 ? upsample_pixel(taps, depth, n, f) : LG_UPSAMPLE_SKY);
    }
}

#endif
