#version 460
#extension GL_GOOGLE_include_directive : require
// env.specular_prefilter's own mip chain, which prefilter.comp's filtered path reads (the
// input's chain, a box per level, stays what env.load's tests check), one dispatch per level:
// level 0 is the input's mip 0 with non-finite radiance as 0; each further level is four
// seamless bilinear reads of the level above, 5/8 of its texel either side of the centre along
// each axis (a separable [1 7 7 1] / 16 of its texels, neighbouring faces across the edges),
// each weighted by its solid angle on the face (1 + x^2 + y^2)^(-3/2) so the chain keeps the
// radiance's integral as the box chain did (unweighted, pisa.hdr's error at roughness 0.25 was
// 0.65% instead of 0.58% in a double-precision emulation). Per level it adds a variance of 1/2
// texel^2 along each axis, against the box's 1/4: the cascade is smoother, nearer a Gaussian
// (prefilter.comp, lod_for_variance). In the emulation the [1 3 3 1] / 8 binomial (3/4 texel^2)
// did as well at roughness 0.5 and 1 but not at 0.25 (0.60% at best), a [1 5 10 10 5 1] / 32
// worse at all three.
#include "nodes/common/shaders/finite.glsl"
#include "nodes/env/common/shaders/cube_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform samplerCube finer;  // the level above
layout(binding = 1, rgba16f) uniform writeonly image2DArray level;
layout(binding = 2) uniform sampler2DArray input_mip0;  // the input's mip 0, for the first level
layout(push_constant) uniform Push {
  uint first;  // 1: copy the input's mip 0
};

// The nearest value an rgba16f texel holds (half's normal range), so the store is exact:
// lavapipe's stores round toward zero, which cascades down the chain, each level from the one
// above (-0.25% RMS at level 7 of a 128^2 cube, pisa.hdr's error at roughness 0.5 0.38% ->
// 0.41% in the emulation).
vec3 nearest_half(vec3 c) {
  return uintBitsToFloat((floatBitsToUint(c) + 0x1000u) & ~0x1FFFu);
}

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int face = int(gl_GlobalInvocationID.z);
  int size = imageSize(level).x;
  if (any(greaterThanEqual(texel, ivec2(size)))) return;
  vec2 uv = (vec2(texel) + 0.5) / float(size);
  vec3 result;
  if (first != 0u) {
    // Fetched, not filtered: a bilinear read at the centre gives a NaN neighbour a zero weight,
    // and 0 x NaN is NaN.
    result = finite_or_zero(texelFetch(input_mip0, ivec3(texel, face), 0).rgb);
  } else {
    float offset = 0.625 / float(2 * size);  // 5/8 of a texel of the level above, in uv
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int k = 0; k < 4; ++k) {
      vec2 p = uv + offset * vec2((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0);
      vec2 x = 2.0 * p - 1.0;
      float q = inversesqrt(1.0 + dot(x, x));
      float w = q * q * q;
      sum += w * textureLod(finer, cube_direction(face, p), 0.0).rgb;
      weight += w;
    }
    result = sum / weight;
  }
  imageStore(level, ivec3(texel, face), vec4(nearest_half(result), 1.0));
}
