#version 460
#extension GL_GOOGLE_include_directive : require
// gi.irradiance_volume's upsample at resolution_scale below 1: the lookup's smaller image back at
// the G-buffer's resolution, guided by its depth and normals (joint_upsample.glsl).
#include "nodes/common/shaders/joint_upsample.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D low_tex;
layout(binding = 1) uniform sampler2D depth_tex;
layout(binding = 2) uniform sampler2D normal_tex;
layout(binding = 3, rgba16f) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  float scale;  // low_tex's resolution over the G-buffer's
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(result)))) return;
  imageStore(result, texel, joint_upsample(low_tex, depth_tex, normal_tex, texel, scale));
}
