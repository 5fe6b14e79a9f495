// NaN and Inf become 0, so one broken texel or light cannot spread through later passes.
// Written with bit tests, as compilers may assume no NaN and fold x != x away; equal(), not ==,
// since == on vectors is one bool, true only when every channel is bad.
#ifndef LG_FINITE_GLSL
#define LG_FINITE_GLSL

vec3 finite_or_zero(vec3 c) {
  bvec3 bad = equal(floatBitsToUint(c) & 0x7f800000u, uvec3(0x7f800000u));
  return any(bad) ? vec3(0.0) : c;
}

#endif
