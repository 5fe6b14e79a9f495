#version 460
#extension GL_GOOGLE_include_directive : require
// post.upsample: an image at 1/k of the G-buffer's resolution brought back to it with the
// depth- and normal-guided weights of joint_upsample.glsl, one invocation per low-resolution
// texel writing its block of k x k pixels. Unlike the effects that upsample their own lighting,
// the image may show the sky, so the sky is handled apart: a sky pixel blends the taps that are
// sky, bilinearly, and a surface whose taps are all sky (thinner than k pixels) takes them
// bilinearly too, rather than 0. NaN and Inf taps count as 0, so they cannot spread.
#include "nodes/common/shaders/finite.glsl"
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D low_tex;
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3, rgba16f) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over low_tex's
};

// Bilinear weights over the taps that are sky, or over all four where none is.
vec4 sky_weights(UpsampleGuide guide, vec2 f) {
  vec4 w = vec4(0.0);
  for (int t = 0; t < 4; ++t) w[t] = guide.depth[t] > 0.0 ? 0.0 : upsample_bilinear(t, f);
  float total = dot(w, vec4(1.0));
  if (total > 0.0) return w / total;
  for (int t = 0; t < 4; ++t) w[t] = upsample_bilinear(t, f);
  return w;
}

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(low_tex, 0), full_size = imageSize(result);
  if (any(greaterThanEqual(low, low_size))) return;
  UpsampleTaps taps = upsample_taps(low_tex, depth_tex, normal_tex, low, k);
  for (int t = 0; t < 4; ++t) taps.value[t] = finite_or_zero(taps.value[t]);
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  for (int y = low.y * k; y < end.y; ++y)
    for (int x = low.x * k; x < end.x; ++x) {
      ivec2 texel = ivec2(x, y);
      vec2 f = upsample_fraction(texel, low, k);
      float depth = texelFetch(depth_tex, texel, 0).r;
      vec4 w = vec4(0.0);
      if (depth > 0.0)
        w = upsample_weights(taps.guide, depth, decode_normal_unnormalized(texelFetch(normal_tex, texel, 0).rgb), f);
      if (!(dot(w, vec4(1.0)) > 0.0)) w = sky_weights(taps.guide, f);
      imageStore(result, texel, w.x * taps.value[0] + w.y * taps.value[1] + w.z * taps.value[2] + w.w * taps.value[3]);
    }
}
