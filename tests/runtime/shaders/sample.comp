// Samples a texture at texel centres shifted by a whole number of repeats and stores what it
// read, to check samplers, combined image samplers and uploads.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba32f) uniform writeonly image2D target;
layout(push_constant) uniform Constants { vec2 shift; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(target);
  if (any(greaterThanEqual(p, size))) return;
  imageStore(target, p, textureLod(source, (vec2(p) + 0.5) / vec2(size) + shift, 0));
}
