#version 460
#extension GL_GOOGLE_include_directive : require
// Adds the radiance the G-buffer's surfaces emit (its emissive target: glTF emissive factor x
// texture, KHR_materials_emissive_strength included) onto the lit image.
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D gbuffer_emissive;
layout(binding = 1, rgba16f) uniform image2D color;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(color)))) return;
  vec4 lit = imageLoad(color, texel);
  vec3 emitted = finite_or_zero(texelFetch(gbuffer_emissive, texel, 0).rgb);
  imageStore(color, texel, vec4(lit.rgb + emitted, lit.a));
}
