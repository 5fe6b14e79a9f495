#version 460
#extension GL_GOOGLE_include_directive : require
// gi.voxel's three outputs at resolution_scale 1/k below 1 back to the G-buffer's resolution in
// one pass, as gi.irradiance_volume's upsample does one image (upsample_pass.glsl): one
// invocation per texel of the smaller images writes its block of G-buffer pixels, each blended
// from the 2 x 2 texels around it guided by depth and normals (joint_upsample.glsl). The guide's
// texels and each pixel's depth, normal and weights are read and computed once for all three (on
// lavapipe the fetches are the cost; three passes of upsample_pass.glsl read the guide three
// times). The sky: no light, unoccluded, no reflection.
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D irradiance_low;
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3, rgba16f) uniform writeonly image2D irradiance;
layout(binding = 4) uniform sampler2D ao_low;
layout(binding = 5, r8) uniform writeonly image2D ao;
layout(binding = 6) uniform sampler2D specular_low;
layout(binding = 7, rgba16f) uniform writeonly image2D specular;
layout(push_constant) uniform Push {
  int k;  // the G-buffer's resolution over the smaller images'
};
// 0 where nothing reads the specular output (voxel_cones.comp's kTraceSpecular): it is not
// written (a specialization constant: lavapipe runs both sides of a run-time branch).
layout(constant_id = 0) const int kSpecular = 1;

// The 2 x 2 texels of `image` from `low`, clamped to its last row and column.
vec4[4] taps(sampler2D image, ivec2 low, ivec2 low_size) {
  vec4 value[4];
  for (int t = 0; t < 4; ++t) value[t] = texelFetch(image, min(low + ivec2(t & 1, t >> 1), low_size - 1), 0);
  return value;
}

vec4 blend(vec4 value[4], vec4 w) {
  return w.x * value[0] + w.y * value[1] + w.z * value[2] + w.w * value[3];
}

void main() {
  ivec2 low = ivec2(gl_GlobalInvocationID.xy);
  ivec2 low_size = textureSize(irradiance_low, 0), full_size = imageSize(irradiance);
  if (any(greaterThanEqual(low, low_size))) return;
  UpsampleGuide guide = upsample_guide(depth_tex, normal_tex, low, k, low_size);
  vec4 e[4] = taps(irradiance_low, low, low_size), a[4] = taps(ao_low, low, low_size), s[4];
  if (kSpecular == 1) s = taps(specular_low, low, low_size);
  ivec2 end = upsample_block_end(low, k, low_size, full_size);
  for (int y = low.y * k; y < end.y; ++y)
    for (int x = low.x * k; x < end.x; ++x) {
      ivec2 texel = ivec2(x, y);
      float depth = texelFetch(depth_tex, texel, 0).r;
      // The sky's values selected, not stored in a branch of their own (on lavapipe every lane
      // would store twice, docs/lavapipe-costs.md rule 1).
      bool sky = !(depth > 0.0);
      vec3 n = decode_normal_unnormalized(texelFetch(normal_tex, texel, 0).rgb);
      vec4 w = upsample_weights(guide, depth, n, upsample_fraction(texel, low, k));
      imageStore(irradiance, texel, sky ? vec4(0.0) : blend(e, w));
      imageStore(ao, texel, sky ? vec4(1.0) : blend(a, w));
      if (kSpecular == 1) imageStore(specular, texel, sky ? vec4(0.0) : blend(s, w));
    }
}
