// Scalar helpers of the area-light shaders: the GLSL twin of area_light_math.h.
#ifndef LG_AREA_LIGHT_MATH_GLSL
#define LG_AREA_LIGHT_MATH_GLSL

const float LG_PI = 3.14159265358979;

// NaN or Inf becomes 0, so one bad G-buffer texel cannot spread through later passes. Written
// with bit tests: compilers may assume no NaN and fold x == x away.
bool is_finite(float x) {
  return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

float finite_or_zero(float x) {
  return is_finite(x) ? x : 0.0;
}

#endif
