#version 460
#extension GL_GOOGLE_include_directive : require
// Evaluates the deferred node's LTC specular (the shader code itself: the table lookup and the
// three lights) on a list of cases, for area_light_ltc_gpu_test.cpp to hold against the C++ twin.
#include "nodes/lighting/deferred/shaders/area_light_ltc.glsl"

layout(local_size_x = 64) in;

struct Case {
  vec4 a;  // sphere: center, radius; tube: end0, radius; rectangle: center, two-sided
  vec4 b;  // tube: end1; rectangle: half_x
  vec4 c;  // rectangle: half_y; w: alpha
  vec4 p;  // w: roughness
  vec4 n;  // w: 0 sphere, 1 tube, 2 rectangle
  vec4 v;  // w: the lobe's directional albedo A + B (Fresnel 1)
};

layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { float integral[]; };
#define LG_LTC_BINDING 2
#include "nodes/lighting/deferred/shaders/ltc_table.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  Case k = cases[i];
  float n_dot_v = max(dot(k.n.xyz, k.v.xyz), 1e-4);
  LtcLobe lobe = ltc_lobe(ltc_lookup(n_dot_v, k.p.w), n_dot_v, k.c.w, k.v.w);
  float e = 0.0;
  if (k.n.w == 0.0) e = ltc_sphere_specular(k.a.xyz, k.a.w, k.p.xyz, k.n.xyz, k.v.xyz, lobe);
  else if (k.n.w == 1.0) e = ltc_tube_specular(k.a.xyz, k.b.xyz, k.a.w, k.p.xyz, k.n.xyz, k.v.xyz, lobe);
  else e = ltc_rect_specular(k.a.xyz, k.b.xyz, k.c.xyz, k.a.w > 0.0, k.p.xyz, k.n.xyz, k.v.xyz, lobe);
  integral[i] = e;
}
