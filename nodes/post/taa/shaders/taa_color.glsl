// post.taa's colour spaces. Radiance is blended and clipped after a reversible tone map,
// c / (1 + max(r, g, b)) (Karis 2014), so one highlight cannot outweigh its neighbourhood and
// its history, and in YCoCg, whose luma axis the neighbourhood's spread mostly lies along (a
// tighter box than in RGB). Both maps are linear or invertible, so blending commutes with them.
#ifndef LG_TAA_COLOR_GLSL
#define LG_TAA_COLOR_GLSL

const float kHalfMax = 65504.0;  // the largest rgba16f value: brighter radiance is clamped to it

// Radiance as the history may hold it: NaN and Inf (any channel) are not usable, negative is 0,
// and values beyond half-float's range clamp to it.
bool usable(vec3 c) {
  return !any(equal(floatBitsToUint(c) & 0x7f800000u, uvec3(0x7f800000u)));
}

vec3 compress(vec3 c) {
  c = clamp(c, 0.0, kHalfMax);
  return c / (1.0 + max(c.r, max(c.g, c.b)));
}

vec3 expand(vec3 t) {
  t = max(t, 0.0);
  return min(t / max(1.0 - max(t.r, max(t.g, t.b)), 1.0 / kHalfMax), vec3(kHalfMax));
}

vec3 rgb_to_ycocg(vec3 c) {
  return vec3(dot(c, vec3(0.25, 0.5, 0.25)), dot(c, vec3(0.5, 0.0, -0.5)), dot(c, vec3(-0.25, 0.5, -0.25)));
}

vec3 ycocg_to_rgb(vec3 c) {
  return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z);
}

#endif
