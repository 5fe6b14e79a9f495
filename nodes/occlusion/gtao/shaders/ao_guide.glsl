// Below resolution_scale 1 each grid texel's occlusion travels beside the surface it stands for
// (its G-buffer pixel's device depth and normal) in one rgba16f texel: horizons.comp writes it
// with the raw occlusion (it has read that depth and normal), the denoiser replaces the
// occlusion, and upsample.comp fetches one image per tap for occlusion and its joint bilateral
// guide, not three (occlusion, G-buffer depth, G-buffer normal). On lavapipe texel fetches are
// the upsample's cost, the G-buffer normal's (rgb10a2, k pixels apart) measured the dearest:
// one more per texel in the denoiser cost +35 ms at load 7, where the denoiser took 15-30.
// Layout: occlusion, device depth carrying the sign of the normal's z, the normal's x and y.
// Half floats keep device depth to 0.05% (the guide's distance term works at 5%) and the normal
// within 2 degrees where z is near 0 (the guide's normal term works at 30).
#ifndef LG_GTAO_AO_GUIDE_GLSL
#define LG_GTAO_AO_GUIDE_GLSL

// `n` unit; `depth` 0 on the sky.
vec4 pack_ao_guide(float occlusion, float depth, vec3 n) {
  return vec4(occlusion, n.z < 0.0 ? -depth : depth, n.x, n.y);
}

struct AoGuide {
  float occlusion, depth;  // depth 0: the sky
  vec3 normal;             // unit within the half floats' precision
};

AoGuide unpack_ao_guide(vec4 packed) {
  float z = sqrt(max(1.0 - dot(packed.zw, packed.zw), 0.0));
  return AoGuide(packed.x, abs(packed.y), vec3(packed.zw, packed.y < 0.0 ? -z : z));
}

#endif
