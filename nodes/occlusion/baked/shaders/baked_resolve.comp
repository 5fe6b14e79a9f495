#version 460
#extension GL_GOOGLE_include_directive : require
// occlusion.baked per pixel: the drawing pass's bake where the nearest surface has one (ao k_A,
// bent normal with cone cosine sqrt(1 - k_A), GTAO's convention); elsewhere open: ao 1 and the
// G-buffer normal (cone cosine 0, the whole hemisphere); the sky ao 1, bent normal 0.
#include "nodes/common/shaders/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D gbuffer_depth;
layout(binding = 1) uniform sampler2D gbuffer_normal;
layout(binding = 2) uniform sampler2D baked;
layout(binding = 3, r8) uniform writeonly image2D ao_out;
layout(binding = 4, rgba8_snorm) uniform writeonly image2D bent_out;
layout(push_constant) uniform Push { uint drawn; };  // 0: the drawing pass was skipped (no bakes)

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, imageSize(ao_out)))) return;
  if (!(texelFetch(gbuffer_depth, texel, 0).r > 0.0)) {
    imageStore(ao_out, texel, vec4(1.0));
    imageStore(bent_out, texel, vec4(0.0));
    return;
  }
  vec4 b = drawn != 0u ? texelFetch(baked, texel, 0) : vec4(-1.0);
  if (b.w < 0.0) {
    imageStore(ao_out, texel, vec4(1.0));
    imageStore(bent_out, texel, vec4(decode_normal(texelFetch(gbuffer_normal, texel, 0).rgb), 0.0));
    return;
  }
  imageStore(ao_out, texel, vec4(b.w));
  imageStore(bent_out, texel, vec4(normalize(b.xyz), sqrt(max(1.0 - b.w, 0.0))));
}
