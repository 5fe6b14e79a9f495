// Fills a 3D r32f image with x + 100 y + 10000 z.
#version 460
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, r32f) uniform writeonly image3D target;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, vec4(p.x + 100 * p.y + 10000 * p.z));
}
