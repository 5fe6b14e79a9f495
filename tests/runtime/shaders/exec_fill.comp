// Executor tests: fills a 2D rgba16f image with (value, x, y, 1); coordinates below 2048 are
// exact in half precision.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Constants { float value; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, vec4(value, p.x, p.y, 1));
}
