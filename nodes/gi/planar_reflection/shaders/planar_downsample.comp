#version 460
#extension GL_GOOGLE_include_directive : require
// gi.planar_reflection's mip chain: one level of one mirrored view from the level above, each
// texel the bilinear tap at the corner its 2x2 source texels share (their mean where the size
// halves evenly). The blur a rough surface reads is a level of this chain.
#include "nodes/common/shaders/finite.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2DArray source;  // the level above
layout(binding = 1, rgba16f) uniform writeonly image2DArray target;
layout(push_constant) uniform Push {  // planar_reflection_kernel.cpp
  uint layer;
};

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(target).xy;
  if (any(greaterThanEqual(texel, size))) return;
  vec2 uv = (vec2(texel) + 0.5) / vec2(size);
  imageStore(target, ivec3(texel, layer), finite_or_zero(textureLod(source, vec3(uv, float(layer)), 0.0)));
}
