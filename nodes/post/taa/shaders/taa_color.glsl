// post.taa's colour spaces. The resolve clips in YCoCg, whose luma axis a neighbourhood's spread
// mostly lies along (a tighter box than in RGB), and blends linear radiance, so that it converges
// to the pixel's box-filtered average, which is what supersampling gives. Blending after the
// reversible tone map c / (1 + max(r, g, b)) (Karis 2014, against flicker of highlights)
// converges to another average at high-contrast edges: it was measured at 0.58 of the unjittered
// frame's error against the supersampled reference (nodes/post/taa/README.md). The sharpening
// works after that tone map, so a highlight does not ring into its surroundings.
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
