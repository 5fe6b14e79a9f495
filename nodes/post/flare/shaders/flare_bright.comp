#version 460
#extension GL_GOOGLE_include_directive : require
// post.flare's first pass: each texel of the low-res grid averages the bright part of its
// divisor x divisor block of the image (pixels past the image's edge count as black), NaN and
// Inf as black and the rest within [0, 65504] (nodes/post/flare/flare_model.h).
#include "nodes/common/shaders/bright_part.glsl"
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D scene_color;
layout(binding = 1, rgba16f) uniform writeonly image2D bright;
layout(push_constant) uniform Push {
  float threshold;  // luminance; 0 for none
  int divisor;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(bright)))) return;
  ivec2 first = texel * divisor, last = min(first + divisor, textureSize(scene_color, 0));
  vec3 sum = vec3(0.0);
  for (int y = first.y; y < last.y; ++y)
    for (int x = first.x; x < last.x; ++x) {
      vec3 c = finite_or_zero(texelFetch(scene_color, ivec2(x, y), 0).rgb);
      sum += bright_part(clamp(c, vec3(0.0), vec3(65504.0)), threshold);
    }
  imageStore(bright, texel, vec4(sum / float(divisor * divisor), 1.0));
}
