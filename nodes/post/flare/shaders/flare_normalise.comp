#version 460
// post.flare's guard: the flare's energy against the bright part's over the whole grid, per
// channel; the composite scales the flare by min(1, bright / flare), the smallest over the
// channels, so the flare never holds more energy than the bright pixels it comes from. One
// workgroup: the grid is a fraction of the frame.
layout(local_size_x = 256) in;

layout(binding = 0) uniform sampler2D bright;
layout(binding = 1) uniform sampler2D flare;
layout(binding = 2, r32f) uniform writeonly image2D guard;

shared vec3 bright_sums[256], flare_sums[256];

void main() {
  uint i = gl_LocalInvocationIndex;
  ivec2 size = textureSize(flare, 0);
  int count = size.x * size.y;
  vec3 b = vec3(0.0), f = vec3(0.0);
  for (int t = int(i); t < count; t += 256) {
    ivec2 texel = ivec2(t % size.x, t / size.x);
    b += texelFetch(bright, texel, 0).rgb;
    f += texelFetch(flare, texel, 0).rgb;
  }
  bright_sums[i] = b;
  flare_sums[i] = f;
  barrier();
  for (uint stride = 128u; stride > 0u; stride >>= 1u) {
    if (i < stride) {
      bright_sums[i] += bright_sums[i + stride];
      flare_sums[i] += flare_sums[i + stride];
    }
    barrier();
  }
  if (i != 0u) return;
  float scale = 1.0;
  for (int c = 0; c < 3; ++c)
    if (flare_sums[0][c] > 0.0) scale = min(scale, bright_sums[0][c] / flare_sums[0][c]);
  imageStore(guard, ivec2(0), vec4(scale, 0.0, 0.0, 0.0));
}
