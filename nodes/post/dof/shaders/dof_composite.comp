#version 460
#extension GL_GOOGLE_include_directive : require
// Sharp where the circle of confusion is under a pixel, the half-resolution blur where it is
// over two, and a blend between.
#include "nodes/post/dof/shaders/dof_constants.glsl"

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
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  vec3 blur = textureLod(blurred, uv, 0.0).rgb;
  vec3 c = mix(sharp, blur, smoothstep(0.5, 2.0, radius));
  imageStore(result, texel, vec4(any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : c, 1.0));
}
