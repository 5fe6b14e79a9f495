// Fills a 2D rgba16f image with an exact function of the texel coordinate (values k/256 are
// exact in half precision), plus a constant that tells two fills apart.
#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Constants { float tag; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(target)))) return;
  imageStore(target, p, vec4(p.x / 256.0, p.y / 256.0, (p.x ^ p.y) / 256.0, tag));
}
