// Diffuse irradiance from sphere, tube (capsule) and rectangle lights: the GLSL twin of
// area_light_formulas.cpp, line by line (see that file and README.md for the derivations and
// the measured errors). Each returns E at p with unit normal n, per unit radiance.
#ifndef LG_AREA_LIGHT_FORMULAS_GLSL
#define LG_AREA_LIGHT_FORMULAS_GLSL

#include "nodes/lighting/deferred/shaders/area_light_math.glsl"

struct HorizonWalk {
  vec3 n;
  vec3 c;
  vec3 c_hat;
  vec3 first;
  vec3 last;
  bool started;
  float sum;
};

HorizonWalk walk_begin(vec3 n, vec3 c) {
  return HorizonWalk(n, c, normalize(c), vec3(0.0), vec3(0.0), false, 0.0);
}

vec3 unit_offset(HorizonWalk walk, vec3 off) {
  vec3 x = walk.c + off;
  float lx = length(x);
  float lc = length(walk.c);
  float k = -dot(2.0 * walk.c + off, off) / (lx * lc * (lx + lc));
  return off / lx + k * walk.c;
}

float great_arc_term(HorizonWalk walk, vec3 a, vec3 b) {
  vec3 chord = b - a;
  vec3 across = cross(walk.c_hat, chord);
  vec3 inner = cross(a, b);
  float s = length(across + inner);
  float t = atan(s, 1.0 - 0.5 * dot(chord, chord));
  float excess = t < 0.1 ? t * t * (1.0 / 6.0 + t * t * (7.0 / 360.0)) : (s > 0.0 ? t / s - 1.0 : 0.0);
  return dot(walk.n, excess * across + (1.0 + excess) * inner);
}

void walk_join(inout HorizonWalk walk, vec3 from_point, vec3 to_point) {
  if (walk.started) {
    walk.sum += great_arc_term(walk, walk.last, from_point);
  } else {
    walk.first = from_point;
    walk.started = true;
  }
  walk.last = to_point;
}

float walk_end(inout HorizonWalk walk) {
  if (walk.started) walk.sum += great_arc_term(walk, walk.last, walk.first);
  return walk.sum;
}

void walk_segment(inout HorizonWalk walk, vec3 off, vec3 edge) {
  float da = dot(walk.n, walk.c) + dot(walk.n, off);
  float db = da + dot(walk.n, edge);
  if (da < 0.0 && db < 0.0) return;
  float t = da / (da - db);
  if (da < 0.0) {
    off = off + t * edge;
    edge = (1.0 - t) * edge;
  } else if (db < 0.0) {
    edge = t * edge;
  }
  vec3 from_point = unit_offset(walk, off);
  vec3 to_point = unit_offset(walk, off + edge);
  walk_join(walk, from_point, to_point);
  walk.sum += great_arc_term(walk, from_point, to_point);
}

struct CircleArc {
  vec3 c;
  vec3 offset;
  vec3 e1;
  vec3 e2;
  float sin_a;
  float one_minus_cos_a;
  float psi_end;
};

vec3 arc_offset(CircleArc arc, float psi) {
  return arc.offset - arc.one_minus_cos_a * arc.c + arc.sin_a * (cos(psi) * arc.e1 + sin(psi) * arc.e2);
}

float arc_term(HorizonWalk walk, CircleArc arc, float psi0, float psi1) {
  float s0 = sin(psi0);
  float s1 = sin(psi1);
  float c0 = cos(psi0);
  float c1 = cos(psi1);
  vec3 integral_e = (s1 - s0) * arc.e1 + (c0 - c1) * arc.e2;
  vec3 change_e = (c1 - c0) * arc.e1 + (s1 - s0) * arc.e2;
  vec3 v = arc.sin_a * arc.sin_a * (psi1 - psi0) * arc.c + arc.sin_a * arc.one_minus_cos_a * integral_e +
           arc.sin_a * cross(arc.offset, change_e);
  return dot(walk.n, v);
}

void walk_arc_part(inout HorizonWalk walk, CircleArc arc, float psi0, float psi1) {
  walk_join(walk, arc_offset(arc, psi0), arc_offset(arc, psi1));
  walk.sum += arc_term(walk, arc, psi0, psi1);
}

void walk_arc(inout HorizonWalk walk, CircleArc arc) {
  float A = (1.0 - arc.one_minus_cos_a) * dot(walk.n, arc.c);
  float B = arc.sin_a * dot(walk.n, arc.e1);
  float C = arc.sin_a * dot(walk.n, arc.e2);
  float R = sqrt(B * B + C * C);
  bool whole = A >= R, none = A <= -R;
  float mid = atan(C, B);
  float half_width = acos(clamp(-A / R, -1.0, 1.0));
  for (int k = 0; k < 2; ++k) {
    float lo = whole ? 0.0 : max(mid - half_width + 2.0 * LG_PI * float(k), 0.0);
    float hi = whole ? arc.psi_end : min(mid + half_width + 2.0 * LG_PI * float(k), arc.psi_end);
    if (!none && (whole ? k == 0 : lo < hi)) walk_arc_part(walk, arc, lo, hi);
  }
}

CircleArc cap_arc(HorizonWalk walk, vec3 off, float radius, vec3 m_from, vec3 m_to) {
  CircleArc arc;
  vec3 center = walk.c + off;
  float dist = length(center);
  arc.c = center / dist;
  arc.offset = unit_offset(walk, off);
  arc.sin_a = min(radius / dist, 1.0);
  arc.one_minus_cos_a = arc.sin_a * arc.sin_a / (1.0 + sqrt(1.0 - arc.sin_a * arc.sin_a));
  arc.e1 = normalize(m_from - dot(m_from, arc.c) * arc.c);
  arc.e2 = cross(arc.c, arc.e1);
  float psi = atan(dot(m_to, arc.e2), dot(m_to, arc.e1));
  arc.psi_end = psi < 0.0 ? psi + 2.0 * LG_PI : psi;
  return arc;
}

float sphere_form_factor(float cos_w, float sin2_a) {
  sin2_a = clamp(sin2_a, 0.0, 1.0);
  if (cos_w * cos_w >= sin2_a) return cos_w > 0.0 ? LG_PI * sin2_a * cos_w : 0.0;
  float sin_a = sqrt(sin2_a);
  float cos_a = sqrt(1.0 - sin2_a);
  float sin_w = sqrt(max(1.0 - cos_w * cos_w, 0.0));
  float y = clamp(-cos_a * cos_w / (sin_a * sin_w), -1.0, 1.0);
  float q = sin_w * sqrt(1.0 - y * y);
  float f = cos_w * acos(y) * sin2_a - cos_a * sin_a * q + atan(q * sin_a, cos_a);
  return max(f, 0.0);
}

float sphere_at(vec3 d, float radius, vec3 n) {
  float dist2 = dot(d, d);
  float cos_w = dist2 > 0.0 ? dot(n, d) / sqrt(dist2) : 0.0;
  float sin2_a = min(radius * radius / dist2, 1.0);
  return finite_or_zero(sphere_form_factor(cos_w, sin2_a));
}

float sphere_irradiance(vec3 center, float radius, vec3 p, vec3 n) {
  if (!(radius > 0.0)) return 0.0;
  return sphere_at(center - p, radius, n / length(n));
}

float tube_irradiance(vec3 end0, vec3 end1, float r, vec3 p, vec3 n) {
  if (!(r > 0.0)) return 0.0;
  n = n / length(n);
  vec3 a = end0 - p;
  vec3 b = end1 - p;
  float len = length(b - a);
  vec3 axis = len > 0.0 ? (b - a) / len : vec3(0.0);
  float along = dot(a, axis);
  vec3 w = a - along * axis;
  float h = length(w);
  if (!(len > 0.0) || !(h > r * 1.00001)) {
    vec3 nearest = a + clamp(-along, 0.0, len) * axis;
    return sphere_at(nearest, r, n);
  }
  vec3 wn = w / h;
  vec3 side = cross(axis, wn);
  float cos_t = r / h;
  float sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
  vec3 m_plus = -cos_t * wn + sin_t * side;
  vec3 m_minus = -cos_t * wn - sin_t * side;

  vec3 half_axis = 0.5 * (end1 - end0);
  HorizonWalk walk = walk_begin(n, a + half_axis);
  walk_segment(walk, -half_axis + r * m_plus, 2.0 * half_axis);
  walk_arc(walk, cap_arc(walk, half_axis, r, m_plus, m_minus));
  walk_segment(walk, half_axis + r * m_minus, -2.0 * half_axis);
  walk_arc(walk, cap_arc(walk, -half_axis, r, m_minus, m_plus));
  return finite_or_zero(max(0.5 * walk_end(walk), 0.0));
}

float rect_irradiance(vec3 center, vec3 hx, vec3 hy, bool two_sided, vec3 p, vec3 n) {
  n = n / length(n);
  vec3 c = center - p;
  if (!two_sided && !(dot(cross(hx, hy), c) < 0.0)) return 0.0;
  HorizonWalk walk = walk_begin(n, c);
  walk_segment(walk, -hx - hy, 2.0 * hx);
  walk_segment(walk, hx - hy, 2.0 * hy);
  walk_segment(walk, hx + hy, -2.0 * hx);
  walk_segment(walk, -hx + hy, -2.0 * hy);
  return finite_or_zero(abs(0.5 * walk_end(walk)));
}

#endif
