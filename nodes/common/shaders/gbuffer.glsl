// How the G-buffer stores a surface (written by scene.gbuffer, read by every lighting pass):
// normal as n * 0.5 + 0.5 in rgb10a2, albedo in rgba8 sRGB (the sampler decodes it) with the
// material's ambient occlusion (glTF occlusion texture; 1: none) in its alpha, which sRGB leaves
// linear, perceptual roughness and metalness in rg8, motion as uv(now) - uv(last frame) in rg16f.
#ifndef LG_GBUFFER_GLSL
#define LG_GBUFFER_GLSL

vec3 encode_normal(vec3 n) {
  return n * 0.5 + 0.5;
}

// A stored normal of zero length (a degenerate mesh normal) decodes to +z, never NaN.
vec3 decode_normal(vec3 stored) {
  vec3 n = stored * 2.0 - 1.0;
  float len = length(n);
  return len > 1e-3 ? n / len : vec3(0.0, 0.0, 1.0);
}

#endif
