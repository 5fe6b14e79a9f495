#version 460
// lighting.ssr's Hi-Z pyramid, one level a dispatch: level 0 copies the G-buffer's device depth,
// every later texel holds the largest of the texels it covers one level down. Depth is reversed Z
// (1 at the near plane, 0 for the sky), so the largest is the nearest surface: a ray in front of a
// texel's value is in front of everything below it. Where the level below has an odd size, the
// last texel of a row or column also takes the one left over, so no depth is lost.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D device_depth;
layout(binding = 1, r32f) uniform readonly image2D below;  // level - 1 (unread for level 0)
layout(binding = 2, r32f) uniform writeonly image2D level_out;
layout(push_constant) uniform Push {
  uint level;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(level_out);
  if (any(greaterThanEqual(texel, size))) return;
  if (level == 0u) {
    float d = texelFetch(device_depth, texel, 0).r;
    bool finite = (floatBitsToUint(d) & 0x7f800000u) != 0x7f800000u;  // a bit test: compilers may fold d != d
    imageStore(level_out, texel, vec4(finite ? clamp(d, 0.0, 1.0) : 0.0));  // NaN or Inf reads as the sky
    return;
  }
  ivec2 below_size = imageSize(below);
  // Covered texels: 2x2, widened to 3 along an axis where this is the last texel of an odd row.
  ivec2 last = min(texel * 2 + 1 + ivec2(equal(texel, size - 1)) * (below_size & 1), below_size - 1);
  float nearest = 0.0;
  for (int y = texel.y * 2; y <= last.y; ++y)
    for (int x = texel.x * 2; x <= last.x; ++x) nearest = max(nearest, imageLoad(below, ivec2(x, y)).r);
  imageStore(level_out, texel, vec4(nearest));
}
