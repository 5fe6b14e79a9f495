// NaN and Inf become 0, so one broken texel or light cannot spread through later passes.
// Written with bit tests, as compilers may assume no NaN and fold x != x away; equal(), not ==,
// since == on vectors is one bool, true only when every channel is bad.
#ifndef LG_FINITE_GLSL
#define LG_FINITE_GLSL

bool all_finite(vec4 c) {
  return !any(equal(floatBitsToUint(c) & 0x7f800000u, uvec4(0x7f800000u)));
}

vec3 finite_or_zero(vec3 c) {
  return all_finite(vec4(c, 0.0)) ? c : vec3(0.0);
}

vec4 finite_or_zero(vec4 c) {
  return all_finite(c) ? c : vec4(0.0);
}

#endif
