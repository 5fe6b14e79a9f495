// Fills every layer of a layered rgba32f image (a cube map's faces) with (x, y, layer, 1).
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2DArray target;

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, vec4(p, 1));
}
