// The cube-map convention of every env node (nodes/env/common/cube_map.h is the same on the
// CPU): faces +X, -X, +Y, -Y, +Z, -Z as array layers 0 to 5, Vulkan's face-to-direction
// mapping, texel (i, j) at u = (i + 0.5) / N, v = (j + 0.5) / N. World up is +Y.
#ifndef LG_CUBE_MAP_GLSL
#define LG_CUBE_MAP_GLSL

// The unit direction through uv in [0, 1]^2 of `face`.
vec3 cube_direction(int face, vec2 uv) {
  vec2 p = uv * 2.0 - 1.0;
  vec3 d;
  if (face == 0) d = vec3(1.0, -p.y, -p.x);
  else if (face == 1) d = vec3(-1.0, -p.y, p.x);
  else if (face == 2) d = vec3(p.x, 1.0, p.y);
  else if (face == 3) d = vec3(p.x, -1.0, -p.y);
  else if (face == 4) d = vec3(p.x, -p.y, 1.0);
  else d = vec3(-p.x, -p.y, -1.0);
  return normalize(d);
}

// Solid angle of the spherical triangle over face-plane points a, b, c (z = 1), whose triple
// product is `det` (Van Oosterom and Strackee). The caller computes det from exact texel
// coordinates, so nothing cancels: differences of atan at corners lose ~1e-3 on small texels.
// The face a direction hits and its uv there; the inverse of cube_direction.
vec2 cube_face_uv(vec3 d, out int face) {
  vec3 m = abs(d);
  vec3 sc_tc_ma;
  if (m.x >= m.y && m.x >= m.z) {
    face = d.x >= 0.0 ? 0 : 1;
    sc_tc_ma = vec3(d.x >= 0.0 ? -d.z : d.z, -d.y, m.x);
  } else if (m.y >= m.z) {
    face = d.y >= 0.0 ? 2 : 3;
    sc_tc_ma = vec3(d.x, d.y >= 0.0 ? d.z : -d.z, m.y);
  } else {
    face = d.z >= 0.0 ? 4 : 5;
    sc_tc_ma = vec3(d.z >= 0.0 ? d.x : -d.x, -d.y, m.z);
  }
  return 0.5 * (sc_tc_ma.xy / sc_tc_ma.z + 1.0);
}

// Small angles (every texel of faces over 4 wide) take atan's series: lavapipe's atan is off
// by about 2e-5 relative.
float cube_triangle_solid_angle(vec3 a, vec3 b, vec3 c, float det) {
  float la = length(a), lb = length(b), lc = length(c);
  float d = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  float t = det / d;
  if (t > 0.1) return 2.0 * atan(det, d);
  float t2 = t * t;
  return 2.0 * t * (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0 - t2 / 9.0))));
}

// The exact solid angle of texel `texel` on a face of `size` texels.
float cube_texel_solid_angle(ivec2 texel, int size) {
  float h = 2.0 / float(size);
  vec2 lo = vec2(texel) * h - 1.0;
  vec3 p00 = vec3(lo, 1.0), p10 = vec3(lo.x + h, lo.y, 1.0);
  vec3 p01 = vec3(lo.x, lo.y + h, 1.0), p11 = vec3(lo + h, 1.0);
  return cube_triangle_solid_angle(p00, p10, p11, h * h) + cube_triangle_solid_angle(p00, p11, p01, h * h);
}

// The face-plane Jacobian dOmega / (dx dy) at face coordinates p in [-1, 1]^2.
float cube_jacobian(vec2 p) {
  float r2 = 1.0 + dot(p, p);
  return 1.0 / (r2 * sqrt(r2));
}

#endif
