#include "nodes/lighting/deferred/area_light_formulas.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/lighting/deferred/area_light_math.h"

namespace lg {
namespace {

// Written as GLSL will read: std:: scalar maths only, structs and in/out parameters.

// The outline of a light is walked piece by piece, keeping what is above the horizon of n,
// summing twice its projected solid angle by Stokes: 2 n.V = n . (closed integral of w x dw).
// Each piece of the outline is a few times the light's angular size, and the pieces cancel to
// the square of that size; summed naively in float a light 50 sizes away loses 4 of 7 digits.
// So each piece's integral is taken less c x (its end - its start), c the direction to the
// light's center, which sums to 0 around the closed outline, and points are kept as offsets
// from c: every term is then of the order of the result.
struct HorizonWalk {
  glm::vec3 n;
  glm::vec3 c;      // the light's center, relative to the shaded point
  glm::vec3 c_hat;  // its direction
  glm::vec3 first;  // offsets from c_hat of the first kept point and of the last
  glm::vec3 last;
  bool started;
  float sum;
};

HorizonWalk walk_begin(glm::vec3 n, glm::vec3 c) {
  return HorizonWalk{n, c, glm::normalize(c), glm::vec3(0.0f), glm::vec3(0.0f), false, 0.0f};
}

// normalize(c + off) - normalize(c), without subtracting two nearly equal unit vectors:
// 1/|x| - 1/|c| = (|c|^2 - |x|^2) / (|x| |c| (|x| + |c|)) and |c|^2 - |x|^2 = -(2c + off).off.
glm::vec3 unit_offset(const HorizonWalk& walk, glm::vec3 off) {
  glm::vec3 x = walk.c + off;
  float lx = glm::length(x);
  float lc = glm::length(walk.c);
  float k = -glm::dot(2.0f * walk.c + off, off) / (lx * lc * (lx + lc));
  return off / lx + k * walk.c;
}

// The great arc between the unit directions c_hat + a and c_hat + b: with the arc's angle t,
// integral of w x dw = (t / sin t) (c_hat + a) x (c_hat + b); less c_hat x (b - a) it is
// (t / sin t - 1) c_hat x (b - a) + (t / sin t) a x b.
float great_arc_term(const HorizonWalk& walk, glm::vec3 a, glm::vec3 b) {
  glm::vec3 chord = b - a;
  glm::vec3 across = glm::cross(walk.c_hat, chord);
  glm::vec3 inner = glm::cross(a, b);
  float s = glm::length(across + inner);
  float t = std::atan2(s, 1.0f - 0.5f * glm::dot(chord, chord));
  // t / sin t - 1 by its series where the division would cancel.
  float excess = t < 0.1f ? t * t * (1.0f / 6.0f + t * t * (7.0f / 360.0f)) : (s > 0.0f ? t / s - 1.0f : 0.0f);
  return glm::dot(walk.n, excess * across + (1.0f + excess) * inner);
}

void walk_join(HorizonWalk& walk, glm::vec3 from, glm::vec3 to) {
  if (walk.started) {
    walk.sum += great_arc_term(walk, walk.last, from);
  } else {
    walk.first = from;
    walk.started = true;
  }
  walk.last = to;
}

float walk_end(HorizonWalk& walk) {
  if (walk.started) walk.sum += great_arc_term(walk, walk.last, walk.first);
  return walk.sum;
}

// A straight edge of the light from c + off to c + off + edge.
void walk_segment(HorizonWalk& walk, glm::vec3 off, glm::vec3 edge) {
  float da = glm::dot(walk.n, walk.c) + glm::dot(walk.n, off);
  float db = da + glm::dot(walk.n, edge);
  if (da < 0.0f && db < 0.0f) return;
  float t = da / (da - db);  // where the edge crosses the horizon, if it does
  if (da < 0.0f) {
    off = off + t * edge;
    edge = (1.0f - t) * edge;
  } else if (db < 0.0f) {
    edge = t * edge;
  }
  glm::vec3 from = unit_offset(walk, off);
  glm::vec3 to = unit_offset(walk, off + edge);
  walk_join(walk, from, to);
  walk.sum += great_arc_term(walk, from, to);
}

// An arc of a circle on the unit sphere: center direction c (offset from the walk's c_hat),
// angular radius a, running counter-clockwise about c (e2 = c x e1) from psi = 0 (along e1)
// to psi_end.
struct CircleArc {
  glm::vec3 c;
  glm::vec3 offset;
  glm::vec3 e1;
  glm::vec3 e2;
  float sin_a;
  float one_minus_cos_a;
  float psi_end;
};

glm::vec3 arc_offset(const CircleArc& arc, float psi) {
  return arc.offset - arc.one_minus_cos_a * arc.c + arc.sin_a * (std::cos(psi) * arc.e1 + std::sin(psi) * arc.e2);
}

// With w = cos(a) c + sin(a) e(psi), e = cos(psi) e1 + sin(psi) e2: integral of w x dw =
// sin^2(a) c dpsi - sin(a) cos(a) integral of e, and c_hat x dw = sin(a) (c x de - offset x de)
// where c x de = -e dpsi. Less c_hat x (end - start) the arc gives
// sin^2(a) c dpsi + sin(a) (1 - cos a) integral of e + sin(a) offset x (e(psi1) - e(psi0)).
float arc_term(const HorizonWalk& walk, const CircleArc& arc, float psi0, float psi1) {
  float s0 = std::sin(psi0);
  float s1 = std::sin(psi1);
  float c0 = std::cos(psi0);
  float c1 = std::cos(psi1);
  glm::vec3 integral_e = (s1 - s0) * arc.e1 + (c0 - c1) * arc.e2;
  glm::vec3 change_e = (c1 - c0) * arc.e1 + (s1 - s0) * arc.e2;
  glm::vec3 v = arc.sin_a * arc.sin_a * (psi1 - psi0) * arc.c + arc.sin_a * arc.one_minus_cos_a * integral_e +
                arc.sin_a * glm::cross(arc.offset, change_e);
  return glm::dot(walk.n, v);
}

void walk_arc_part(HorizonWalk& walk, const CircleArc& arc, float psi0, float psi1) {
  walk_join(walk, arc_offset(arc, psi0), arc_offset(arc, psi1));
  walk.sum += arc_term(walk, arc, psi0, psi1);
}

// n.w(psi) = A + B cos(psi) + C sin(psi) is >= 0 on one interval of the circle (or on all or
// none of it); the arc [0, psi_end] meets that interval in at most two parts.
void walk_arc(HorizonWalk& walk, const CircleArc& arc) {
  float A = (1.0f - arc.one_minus_cos_a) * glm::dot(walk.n, arc.c);
  float B = arc.sin_a * glm::dot(walk.n, arc.e1);
  float C = arc.sin_a * glm::dot(walk.n, arc.e2);
  float R = std::sqrt(B * B + C * C);
  // All above the horizon (the whole arc is the first part) or all below (no part). Two parts,
  // not a third for the whole arc: a GPU (lavapipe too) runs every part its lanes disagree on.
  bool whole = A >= R, none = A <= -R;
  float mid = std::atan2(C, B);
  float half = std::acos(std::fmin(std::fmax(-A / R, -1.0f), 1.0f));
  for (int k = 0; k < 2; ++k) {
    float lo = whole ? 0.0f : std::fmax(mid - half + 2.0f * kAreaLightPi * float(k), 0.0f);
    float hi = whole ? arc.psi_end : std::fmin(mid + half + 2.0f * kAreaLightPi * float(k), arc.psi_end);
    if (!none && (whole ? k == 0 : lo < hi)) walk_arc_part(walk, arc, lo, hi);
  }
}

// The silhouette arc of the capsule's end sphere at walk.c + off: from the tangent point of
// generator direction m_from to that of m_to, counter-clockwise about the sphere's center.
CircleArc cap_arc(const HorizonWalk& walk, glm::vec3 off, float radius, glm::vec3 m_from, glm::vec3 m_to) {
  CircleArc arc;
  glm::vec3 center = walk.c + off;
  float dist = glm::length(center);
  arc.c = center / dist;
  arc.offset = unit_offset(walk, off);
  arc.sin_a = std::fmin(radius / dist, 1.0f);
  arc.one_minus_cos_a = arc.sin_a * arc.sin_a / (1.0f + std::sqrt(1.0f - arc.sin_a * arc.sin_a));
  // Tangent points lie at center + radius * m; their directions about c are m's parts across c.
  arc.e1 = glm::normalize(m_from - glm::dot(m_from, arc.c) * arc.c);
  arc.e2 = glm::cross(arc.c, arc.e1);
  float psi = std::atan2(glm::dot(m_to, arc.e2), glm::dot(m_to, arc.e1));
  arc.psi_end = psi < 0.0f ? psi + 2.0f * kAreaLightPi : psi;
  return arc;
}

// The irradiance of a sphere whose center is at d from the shaded point.
float sphere_at(glm::vec3 d, float radius, float radiance, glm::vec3 n) {
  float dist2 = glm::dot(d, d);
  float cos_w = dist2 > 0.0f ? glm::dot(n, d) / std::sqrt(dist2) : 0.0f;
  float sin2_a = std::fmin(radius * radius / dist2, 1.0f);
  return finite_or_zero(radiance * sphere_form_factor(cos_w, sin2_a));
}

}  // namespace

float sphere_form_factor(float cos_w, float sin2_a) {
  sin2_a = clamp01(sin2_a);
  // Entirely above (or below) the horizon: the cone's projected solid angle is pi sin^2 a cos w.
  if (cos_w * cos_w >= sin2_a) return cos_w > 0.0f ? kAreaLightPi * sin2_a * cos_w : 0.0f;
  // Straddling it (here sin a > 0 and sin w > 0): Snyder's closed form, with atan(q / cot a)
  // written as atan2 so that a touching sphere (cot a = 0) needs no division.
  float sin_a = std::sqrt(sin2_a);
  float cos_a = std::sqrt(1.0f - sin2_a);
  float sin_w = std::sqrt(std::fmax(1.0f - cos_w * cos_w, 0.0f));
  float y = std::fmin(std::fmax(-cos_a * cos_w / (sin_a * sin_w), -1.0f), 1.0f);
  float q = sin_w * std::sqrt(1.0f - y * y);
  float f = cos_w * std::acos(y) * sin2_a - cos_a * sin_a * q + std::atan2(q * sin_a, cos_a);
  // The terms cancel to a sliver where the sphere barely clears the horizon: keep rounding >= 0.
  return std::fmax(f, 0.0f);
}

float sphere_irradiance(const SphereLight& light, glm::vec3 p, glm::vec3 n) {
  if (!(light.radius > 0.0f)) return 0.0f;
  return sphere_at(light.center - p, light.radius, light.radiance, n / glm::length(n));
}

float tube_irradiance(const TubeLight& light, glm::vec3 p, glm::vec3 n) {
  float r = light.radius;
  if (!(r > 0.0f)) return 0.0f;
  n = n / glm::length(n);
  glm::vec3 a = light.end0 - p;
  glm::vec3 b = light.end1 - p;
  float len = glm::length(b - a);
  glm::vec3 axis = len > 0.0f ? (b - a) / len : glm::vec3(0.0f);
  float along = glm::dot(a, axis);
  glm::vec3 w = a - along * axis;  // from p to the axis line, across it
  float h = glm::length(w);
  // Within the cylinder's radius of the axis only the nearer end sphere shows (or p is inside,
  // and gets the touching limit). The margin keeps the two generators below apart.
  if (!(len > 0.0f) || !(h > r * 1.00001f)) {
    glm::vec3 nearest = a + std::fmin(std::fmax(-along, 0.0f), len) * axis;
    return sphere_at(nearest, r, light.radiance, n);
  }
  // The generator lines of the silhouette touch the cylinder at radius * m+ and radius * m-,
  // where w.m = -radius. Taking m+ toward axis x w makes the outline counter-clockwise.
  glm::vec3 wn = w / h;
  glm::vec3 side = glm::cross(axis, wn);
  float cos_t = r / h;
  float sin_t = std::sqrt(std::fmax(1.0f - cos_t * cos_t, 0.0f));
  glm::vec3 m_plus = -cos_t * wn + sin_t * side;
  glm::vec3 m_minus = -cos_t * wn - sin_t * side;

  glm::vec3 half = 0.5f * (light.end1 - light.end0);
  HorizonWalk walk = walk_begin(n, a + half);
  walk_segment(walk, -half + r * m_plus, 2.0f * half);
  walk_arc(walk, cap_arc(walk, half, r, m_plus, m_minus));
  walk_segment(walk, half + r * m_minus, -2.0f * half);
  walk_arc(walk, cap_arc(walk, -half, r, m_minus, m_plus));
  return finite_or_zero(light.radiance * std::fmax(0.5f * walk_end(walk), 0.0f));
}

float rect_irradiance(const RectLight& light, glm::vec3 p, glm::vec3 n) {
  n = n / glm::length(n);
  glm::vec3 c = light.center - p;
  glm::vec3 hx = light.half_x;
  glm::vec3 hy = light.half_y;
  // A one-sided light is seen only from in front of its plane.
  if (!light.two_sided && !(glm::dot(glm::cross(hx, hy), c) < 0.0f)) return 0.0f;
  HorizonWalk walk = walk_begin(n, c);
  walk_segment(walk, -hx - hy, 2.0f * hx);
  walk_segment(walk, hx - hy, 2.0f * hy);
  walk_segment(walk, hx + hy, -2.0f * hx);
  walk_segment(walk, -hx + hy, -2.0f * hy);
  // Seen from behind the outline turns clockwise and the sum changes sign only.
  return finite_or_zero(light.radiance * std::fabs(0.5f * walk_end(walk)));
}

}  // namespace lg
