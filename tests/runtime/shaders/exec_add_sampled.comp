// Executor tests: target = source + (add, 0, 0, 0), the source read through a sampler.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Constants { float add; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, texelFetch(source, p, 0) + vec4(add, 0, 0, 0));
}
