// Tone curves from scene-referred linear Rec.709 to display-referred linear [0, 1], and the
// sRGB transfer function. Shared by the tonemap pass and its tests.
#ifndef LG_TONE_CURVES_GLSL
#define LG_TONE_CURVES_GLSL

// Stephen Hill's fit of the ACES reference rendering and sRGB output transforms: into the
// RRT's working space, a rational fit of RRT + ODT, and back.
vec3 aces_fitted(vec3 c) {
  const mat3 to_rrt = transpose(mat3(0.59719, 0.35458, 0.04823,
                                     0.07600, 0.90834, 0.01566,
                                     0.02840, 0.13383, 0.83777));
  const mat3 from_odt = transpose(mat3(1.60475, -0.53108, -0.07367,
                                       -0.10208, 1.10813, -0.00605,
                                       -0.00327, -0.07276, 1.07602));
  vec3 v = to_rrt * c;
  vec3 fitted = (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081);
  return clamp(from_odt * fitted, 0.0, 1.0);
}

// Khronos PBR Neutral: identity below 0.76, then a smooth shoulder on the brightest channel
// that keeps hue, desaturating only highlights beyond display white.
vec3 neutral(vec3 c) {
  const float start = 0.8 - 0.04;
  const float desaturation = 0.15;
  float x = min(c.r, min(c.g, c.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  float peak = max(c.r, max(c.g, c.b));
  if (peak < start) return clamp(c, 0.0, 1.0);
  float d = 1.0 - start;
  float new_peak = 1.0 - d * d / (peak + d - start);
  c *= new_peak / peak;
  float g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
  return clamp(mix(c, vec3(new_peak), g), 0.0, 1.0);
}

vec3 srgb_encode(vec3 linear) {
  vec3 lo = linear * 12.92;
  vec3 hi = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
  return mix(hi, lo, lessThanEqual(linear, vec3(0.0031308)));
}

#endif
