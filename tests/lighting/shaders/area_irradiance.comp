#version 460
#extension GL_GOOGLE_include_directive : require
// Evaluates the deferred node's area-light diffuse formulas (the shader code itself) on a list
// of cases, for area_light_gpu_test.cpp to hold against the double-precision reference.
#include "nodes/lighting/deferred/shaders/area_light_formulas.glsl"

layout(local_size_x = 64) in;

struct Case {
  vec4 a;  // sphere: center, radius; tube: end0, radius; rectangle: center, two-sided
  vec4 b;  // tube: end1; rectangle: half_x
  vec4 c;  // rectangle: half_y
  vec4 p;
  vec4 n;  // w: 0 sphere, 1 tube, 2 rectangle
};

layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { float irradiance[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  Case k = cases[i];
  float e = 0.0;
  if (k.n.w == 0.0) e = sphere_irradiance(k.a.xyz, k.a.w, k.p.xyz, k.n.xyz);
  else if (k.n.w == 1.0) e = tube_irradiance(k.a.xyz, k.b.xyz, k.a.w, k.p.xyz, k.n.xyz);
  else e = rect_irradiance(k.a.xyz, k.b.xyz, k.c.xyz, k.a.w > 0.0, k.p.xyz, k.n.xyz);
  irradiance[i] = e;
}
