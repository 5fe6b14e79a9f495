#version 460
#extension GL_GOOGLE_include_directive : require
// occlusion.gtao's upsample at resolution_scale 1/k below 1: the denoised, accumulated occlusion
// and the bent normals of the horizon grid brought back to the G-buffer's resolution, both with
// one set of depth- and normal-guided weights (joint_upsample.glsl), so occlusion does not leak
// across a silhouette. One invocation per grid texel writes its block of k x k pixels.
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D ao_low;
layout(binding = 1) uniform sampler2D bent_low;
layout(binding = 2) uniform sampler2D depth_tex;
layout(binding = 3) uniform sampler2D normal_tex;
layout(binding = 4, r8) uniform writeonly image2D ao;
layout(binding = 5, rgba8_snorm) uniform writeonly image2D bent_normals;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the grid's
};

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(ao_low, 0), full_size = imageSize(ao);
  if (any(greaterThanEqual(low, low_size))) return;
  UpsampleGuide guide = upsample_guide(depth_tex, normal_tex, low, k, low_size);
  vec4 occlusion;
  vec4 bent[4];
  for (int t = 0; t < 4; ++t) {
    ivec2 texel = min(low + ivec2(t & 1, t >> 1), low_size - 1);
    occlusion[t] = texelFetch(ao_low, texel, 0).r;
    bent[t] = texelFetch(bent_low, texel, 0);
  }
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  for (int y = low.y * k; y < end.y; ++y)
    for (int x = low.x * k; x < end.x; ++x) {
      ivec2 texel = ivec2(x, y);
      float depth = texelFetch(depth_tex, texel, 0).r;
      // The sky, and a surface whose taps are all sky (thinner than k pixels against it), are
      // unoccluded, as horizons.comp writes the sky.
      float visibility = 1.0;
      vec4 cone = vec4(0.0);
      if (depth > 0.0) {
        vec3 stored = texelFetch(normal_tex, texel, 0).rgb;
        vec4 w = upsample_weights(guide, depth, decode_normal_unnormalized(stored), upsample_fraction(texel, low, k));
        if (dot(w, vec4(1.0)) > 0.0) {
          visibility = dot(w, occlusion);
          cone = w.x * bent[0] + w.y * bent[1] + w.z * bent[2] + w.w * bent[3];
          float length_xyz = length(cone.xyz);
          cone.xyz = length_xyz > 1e-6 ? cone.xyz / length_xyz : decode_normal(stored);
        } else {
          cone = vec4(decode_normal(stored), 0.0);
        }
      }
      imageStore(ao, texel, vec4(visibility));
      imageStore(bent_normals, texel, cone);
    }
}
