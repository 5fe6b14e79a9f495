#version 460
#extension GL_GOOGLE_include_directive : require
// Moves `intensity` of each pixel's blooming radiance into the blurred chain (the chain's
// levels averaged), so the frame's total radiance is unchanged: out = c + k (bloom - bright(c)).
#include "nodes/common/shaders/bright_part.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1) uniform sampler2D chain;  // level 0, holding the sum of all levels
layout(binding = 2, rgba16f) uniform writeonly image2D result;
layout(push_constant) uniform Push {
  float intensity;
  float threshold;
  float levels;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(result);
  if (any(greaterThanEqual(texel, size))) return;
  vec3 c = texelFetch(scene_color, texel, 0).rgb;
  if (any(isnan(c)) || any(isinf(c))) c = vec3(0.0);
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  vec3 bloom = textureLod(chain, uv, 0.0).rgb / levels;
  imageStore(result, texel, vec4(max(c + intensity * (bloom - bright_part(c, threshold)), vec3(0.0)), 1.0));
}
