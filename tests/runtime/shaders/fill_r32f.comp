// Fills a 2D r32f image with x * 1000 + y + tag, exact in single precision.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, r32f) uniform writeonly image2D target;
layout(push_constant) uniform Constants { float tag; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, vec4(p.x * 1000 + p.y + tag));
}
