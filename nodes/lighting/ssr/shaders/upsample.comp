#version 460
#extension GL_GOOGLE_include_directive : require
// lighting.ssr's upsample at resolution_scale 1/k below 1: the resolved reflections of the trace's
// grid brought back to the G-buffer's resolution with depth- and normal-guided weights
// (joint_upsample.glsl), so a reflection does not leak across a silhouette. Blended premultiplied
// by confidence, as the resolve blends, so a tap without a hit lowers the confidence rather than
// darkening the radiance. Pixels the trace would skip (the sky, too rough) get 0. One invocation
// per grid texel writes its block of k x k pixels.
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D resolved;  // rgb reflected radiance, a confidence
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3) uniform sampler2D material_tex;  // r: perceptual roughness
layout(binding = 4, rgba16f) uniform writeonly image2D reflections;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the grid's
  float max_roughness;
};

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(resolved, 0), full_size = imageSize(reflections);
  if (any(greaterThanEqual(low, low_size))) return;
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  // Where none of the four texels has a hit (the sky, rough surfaces, misses: most of a frame)
  // the block is 0, and neither the guide nor the pixels' surfaces need reading.
  vec4 value[4];
  float confidence = 0.0;
  for (int t = 0; t < 4; ++t) {
    value[t] = texelFetch(resolved, min(low + ivec2(t & 1, t >> 1), low_size - 1), 0);
    value[t].rgb *= value[t].a;
    confidence = max(confidence, value[t].a);
  }
  if (!(confidence > 0.0)) {
    for (int y = low.y * k; y < end.y; ++y)
      for (int x = low.x * k; x < end.x; ++x) imageStore(reflections, ivec2(x, y), vec4(0.0));
    return;
  }
  UpsampleTaps taps;
  taps.guide = upsample_guide(depth_tex, normal_tex, low, k, low_size);
  taps.value = value;
  for (int y = low.y * k; y < end.y; ++y)
    for (int x = low.x * k; x < end.x; ++x) {
      ivec2 texel = ivec2(x, y);
      float depth = texelFetch(depth_tex, texel, 0).r;
      vec4 result = vec4(0.0);
      if (depth > 0.0 && texelFetch(material_tex, texel, 0).r < max_roughness) {
        vec3 n = decode_normal_unnormalized(texelFetch(normal_tex, texel, 0).rgb);
        vec4 c = upsample_pixel(taps, depth, n, upsample_fraction(texel, low, k));
        if (c.a > 0.0) result = vec4(min(c.rgb / c.a, vec3(65504.0)), min(c.a, 1.0));
      }
      imageStore(reflections, texel, result);
    }
}
