#version 460
// Adds the level below, upsampled with a 3x3 tent of bilinear taps, onto this level: after the
// last step level 0 holds the sum of every level's blur.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D coarser;
layout(binding = 1, rgba16f) uniform image2D target;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(target);
  if (any(greaterThanEqual(texel, size))) return;
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  vec2 d = 1.0 / vec2(textureSize(coarser, 0));
  vec3 sum = vec3(0.0);
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      float w = (x == 0 ? 2.0 : 1.0) * (y == 0 ? 2.0 : 1.0);
      sum += w * textureLod(coarser, uv + vec2(x, y) * d, 0.0).rgb;
    }
  imageStore(target, texel, vec4(imageLoad(target, texel).rgb + sum / 16.0, 1.0));
}
