// How the G-buffer stores a surface (written by scene.gbuffer, read by every lighting pass):
// the normal in rgb10a2 (below), albedo in rgba8 sRGB (the sampler decodes it) with the
// material's ambient occlusion (glTF occlusion texture; 1: none) in its alpha, which sRGB leaves
// linear, perceptual roughness and metalness in rg8, motion as uv(now) - uv(last frame) in rg16f,
// emitted radiance in rgba16f.
// nodes/common/gbuffer_normal.h is the C++ twin of the normal's encoding.
#ifndef LG_GBUFFER_GLSL
#define LG_GBUFFER_GLSL

// Each component maps [-1, 1] onto the steps 0..1022 of the 10-bit channel, so -1, 0 and 1 are
// stored exactly: n * 0.5 + 0.5 would put 0 at 511.5 / 1023, between two steps, and tilt every
// axis-aligned normal by 1.4 mrad, which a smooth metal's highlight resolves.
vec3 encode_normal(vec3 n) {
  return (n * 511.0 + 511.0) / 1023.0;
}

// The stored normal before normalization: unit length within the channel's steps (about 0.2%),
// for comparing normals where that error does not matter; a degenerate normal stays 0.
vec3 decode_normal_unnormalized(vec3 stored) {
  return (stored * 1023.0 - 511.0) / 511.0;
}

// A stored normal of zero length (a degenerate mesh normal) decodes to +z, never NaN.
vec3 decode_normal(vec3 stored) {
  vec3 n = decode_normal_unnormalized(stored);
  float len = length(n);
  return len > 1e-3 ? n / len : vec3(0.0, 0.0, 1.0);
}

#endif
