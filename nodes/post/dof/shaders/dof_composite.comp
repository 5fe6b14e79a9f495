#version 460
#extension GL_GOOGLE_include_directive : require
// Sharp where the circle of confusion is under half a pixel, the blurred layer where it is over
// two, and a blend between.
#include "nodes/post/dof/shaders/dof_constants.glsl"
#include "nodes/post/dof/shaders/dof_blend.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D coc;
layout(binding = 2) uniform sampler2D blurred;
layout(binding = 3, rgba16f) uniform writeonly image2D result;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(result);
  if (any(greaterThanEqual(texel, size))) return;
  vec3 sharp = texelFetch(scene_color, texel, 0).rgb;
  float radius = abs(texelFetch(coc, texel, 0).r);
  vec3 blur = texelFetch(blurred, texel, 0).rgb;
  vec3 c = mix(sharp, blur, defocus_blend(radius));
  imageStore(result, texel, vec4(any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : c, 1.0));
}
