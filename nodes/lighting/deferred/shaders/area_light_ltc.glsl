// Area-light specular by linearly transformed cosines: the GLSL twin of area_light_ltc.cpp (which
// states the method). Each returns I, the fraction of the GGX lobe's energy the light covers (the
// caller multiplies by the radiance), corrected for the LTC's shape at the light
// (ltc_shape_corrected).
#ifndef LG_AREA_LIGHT_LTC_GLSL
#define LG_AREA_LIGHT_LTC_GLSL

#include "nodes/common/shaders/brdf.glsl"
#include "nodes/lighting/deferred/shaders/area_light_math.glsl"

// As area_light_ltc.h's, once a pixel: ltc_lookup(n.v, roughness) (ltc_table.glsl), alpha, the
// lobe's directional albedo A + B with Fresnel 1 and the view in the frame of n and v.
struct LtcLobe {
  vec4 entry;
  float alpha;
  float albedo;
  vec3 view;
};

LtcLobe ltc_lobe(vec4 entry, float n_dot_v, float alpha, float albedo) {
  return LtcLobe(entry, alpha, albedo, vec3(sqrt(max(1.0 - n_dot_v * n_dot_v, 0.0)), 0.0, n_dot_v));
}

const int LG_LTC_ARC_SEGMENTS = 4;
const int LG_LTC_OUTLINE_VERTICES = 2 * (LG_LTC_ARC_SEGMENTS + 1);

vec3 ltc_any_perpendicular(vec3 n) {
  return normalize(cross(n, abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
}

float ltc_specular_result(float integral) {
  return clamp(finite_or_zero(integral), 0.0, 1.0);
}

mat3 ltc_to_cosine(vec3 n, vec3 v, vec4 e) {
  n = normalize(n);
  vec3 t1 = v - n * dot(n, v);
  float len = length(t1);
  t1 = len > 1e-6 ? t1 / len : ltc_any_perpendicular(n);
  vec3 t2 = cross(n, t1);
  mat3 m_inv = mat3(vec3(e.x, 0.0, e.z), vec3(0.0, 1.0, 0.0), vec3(e.y, 0.0, e.w));
  return m_inv * transpose(mat3(t1, t2, n));
}

vec3 ltc_edge_term(vec3 a, vec3 b) {
  vec3 e0 = normalize(a), e1 = normalize(b);
  vec3 c = cross(e0, e1);
  float s = length(c);
  return s > 0.0 ? c * atan(s, dot(e0, e1)) / s : vec3(0.0);
}

// Where edge a-b crosses the plane through the origin at signed distances da, db (a's, b's);
// a when they do not straddle it, so that the caller's selects never see a division by zero.
vec3 ltc_crossing(vec3 a, vec3 b, float da, float db) {
  float denom = da - db;
  return a + (b - a) * (denom != 0.0 ? da / denom : 0.0);
}

struct LtcCosineClip {
  vec3 sum;  // 2 pi F
  vec3 exit_;
  vec3 entry;
  bool exited;
  bool entered;
};

struct LtcPolygon {
  vec3 n;
  mat3 to_cosine;
  vec3 exit_;
  vec3 entry;
  bool exited;
  bool entered;
  LtcCosineClip cosine;
};

LtcPolygon ltc_polygon(vec3 n, vec3 v, vec4 entry) {
  LtcCosineClip c = LtcCosineClip(vec3(0.0), vec3(0.0), vec3(0.0), false, false);
  return LtcPolygon(normalize(n), ltc_to_cosine(n, v, entry), vec3(0.0), vec3(0.0), false, false, c);
}

// The clips choose the kept part's ends by selects and take one edge term, not one per case:
// lavapipe runs every side of a branch its lanes disagree on (as GPUs do), and the edge term
// (normalize, cross, atan) is the costly part.
void ltc_add_cosine_edge(inout LtcCosineClip c, vec3 a, vec3 b) {
  bool a_in = a.z > 0.0, b_in = b.z > 0.0;
  vec3 x = ltc_crossing(a, b, a.z, b.z);
  if (a_in && !b_in) {
    c.exit_ = x;
    c.exited = true;
  }
  if (b_in && !a_in) {
    c.entry = x;
    c.entered = true;
  }
  vec3 term = ltc_edge_term(a_in ? a : x, b_in ? b : x);
  c.sum += a_in || b_in ? term : vec3(0.0);
}

void ltc_add_edge(inout LtcPolygon poly, vec3 a, vec3 b) {
  float da = dot(poly.n, a), db = dot(poly.n, b);
  bool a_in = da > 0.0, b_in = db > 0.0;
  vec3 x = ltc_crossing(a, b, da, db);
  if (a_in && !b_in) {
    poly.exit_ = x;
    poly.exited = true;
  }
  if (b_in && !a_in) {
    poly.entry = x;
    poly.entered = true;
  }
  // An edge wholly below the horizon becomes the point x, which adds nothing.
  ltc_add_cosine_edge(poly.cosine, poly.to_cosine * (a_in ? a : x), poly.to_cosine * (b_in ? b : x));
}

float ltc_finish(inout LtcPolygon poly) {
  // The horizon's chord where the surface clip cut the polygon (a point, adding nothing, where not).
  bool cut = poly.exited && poly.entered;
  ltc_add_cosine_edge(poly.cosine, poly.to_cosine * poly.exit_, poly.to_cosine * (cut ? poly.entry : poly.exit_));
  bool cosine_cut = poly.cosine.exited && poly.cosine.entered;
  vec3 chord = ltc_edge_term(poly.cosine.exit_, poly.cosine.entry);
  poly.cosine.sum += cosine_cut ? chord : vec3(0.0);
  return abs(poly.cosine.sum.z) / (2.0 * LG_PI);
}

vec3 ltc_form_factor(LtcPolygon poly) {
  return poly.cosine.sum * ((poly.cosine.sum.z < 0.0 ? -1.0 : 1.0) / (2.0 * LG_PI));
}

struct LtcOutline {
  vec3 end0;
  vec3 end1;
  float radius0;
  float radius1;
  vec3 along;
  vec3 axis0;
  vec3 axis1;
  vec3 side0;
  vec3 side1;
  float span0;  // each end's arc: psi either side of its middle
  float span1;
  float inner0;  // its inner corners' radius over the end's
  float inner1;
  bool round_;
};

// End k's arc across the ray to it (w): the outline's along direction made perpendicular to w,
// and the side direction.
void ltc_end_frame(vec3 end_, vec3 along, out vec3 axis, out vec3 side) {
  vec3 w = normalize(end_);
  vec3 across = along - w * dot(along, w);
  float across_len = length(across);
  axis = across_len > 1e-6 ? across / across_len : along;
  side = normalize(cross(w, axis));
}

// End k's arc's half-span: where the cylinder's silhouette line (at offset from the end's
// centre e) meets the end's disk, psi from the arc's middle (middle_sign * axis), as
// area_light_ltc.cpp's ltc_capsule_outline; a half circle where the point is within the
// cylinder's reach.
float ltc_end_span(vec3 e, vec3 offset, vec3 end_, vec3 axis, vec3 side, float middle_sign, bool beside) {
  vec3 touch = e + offset;
  float along_ray = dot(touch, normalize(end_));
  vec3 q = touch * (length(end_) / along_ray) - end_;
  float psi = atan(abs(dot(q, side)), middle_sign * dot(q, axis));
  return beside && along_ray > 0.0 ? psi : 0.5 * LG_PI;
}

float ltc_inner_radius(float span) {
  float segments = float(LG_LTC_ARC_SEGMENTS);
  return (sqrt(1.0 + (segments - 2.0) * 2.0 * span / sin(2.0 * span / segments)) - 1.0) / (segments - 2.0);
}

bool ltc_capsule_outline(vec3 a, vec3 b, float radius, vec3 n, out LtcOutline o) {
  o = LtcOutline(a, b, 0.0, 0.0, vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0, 0.0, 0.0, 0.0, false);
  vec3 c = 0.5 * (a + b);
  float dc = length(c);
  if (!(dc > 0.0) || !(radius > 0.0)) return false;
  vec3 u = c / dc;
  float depth = max(dot(a, u), 1e-3 * dc);
  float scale = dc / depth;
  o.end0 = a * scale + u * (dc - dot(a, u) * scale);
  float d2 = dot(a, a);
  o.radius0 = radius * sqrt(d2) * scale / sqrt(max(d2 - radius * radius, 1e-6 * d2));
  depth = max(dot(b, u), 1e-3 * dc);
  scale = dc / depth;
  o.end1 = b * scale + u * (dc - dot(b, u) * scale);
  d2 = dot(b, b);
  o.radius1 = radius * sqrt(d2) * scale / sqrt(max(d2 - radius * radius, 1e-6 * d2));
  vec3 axis = o.end1 - o.end0;
  float len = length(axis);
  o.round_ = !(len > 1e-6 * dc);
  if (!o.round_) {
    o.along = axis / len;
  } else {
    vec3 in_plane = n - u * dot(n, u);
    o.along = length(in_plane) > 1e-6 ? normalize(in_plane) : ltc_any_perpendicular(u);
    float sides = float(LG_LTC_OUTLINE_VERTICES);
    o.radius0 = max(o.radius0, o.radius1) * sqrt(2.0 * LG_PI / (sides * sin(2.0 * LG_PI / sides)));
    o.radius1 = o.radius0;
  }
  ltc_end_frame(o.end0, o.along, o.axis0, o.side0);
  ltc_end_frame(o.end1, o.along, o.axis1, o.side1);
  vec3 dir = o.round_ ? vec3(0.0) : normalize(b - a);
  vec3 foot = a - dir * dot(a, dir);
  float h = length(foot);
  bool beside = !o.round_ && h > radius * 1.0001;
  vec3 toward = h > 0.0 ? -foot / h : vec3(0.0), side = cross(dir, toward);
  float ratio = radius / max(h, radius);
  vec3 offset = radius * (ratio * toward + sqrt(1.0 - ratio * ratio) * side);
  o.span0 = ltc_end_span(a, offset, o.end0, o.axis0, o.side0, -1.0, beside);
  o.span1 = ltc_end_span(b, offset, o.end1, o.axis1, o.side1, 1.0, beside);
  o.inner0 = ltc_inner_radius(o.span0);
  o.inner1 = ltc_inner_radius(o.span1);
  return true;
}

// Corner (cos, sin) of end 0's (or end 1's) polygon at `radius` times the end's, as
// area_light_ltc.cpp's ltc_outline_vertex.
vec3 ltc_outline_point(LtcOutline o, bool end1, vec2 cs, float radius) {
  return end1 ? o.end1 + radius * o.radius1 * (cs.x * o.axis1 + cs.y * o.side1)
              : o.end0 + radius * o.radius0 * (cs.x * o.axis0 + cs.y * o.side0);
}

// The outline's corners in the C++ ltc_outline_vertex's order, each angle one step on from the
// last by a rotation, not a cos and a sin per corner (with both outlines' angles taken, since
// lavapipe runs both sides of round_'s selects, that was 20 sines and cosines a light). A round
// outline starts at pi / 2 and steps 2 pi / N; a capsule's end 0 runs from pi - span0 to
// pi + span0, end 1's from -span1 to span1, each in LG_LTC_ARC_SEGMENTS steps.
vec3 ltc_capsule_form_factor(vec3 a, vec3 b, float radius, vec3 n, vec3 v, vec4 entry) {
  LtcOutline o;
  if (!ltc_capsule_outline(a, b, radius, n, o)) return vec3(0.0);
  LtcPolygon poly = ltc_polygon(n, v, entry);
  const float round_step = 2.0 * LG_PI / float(LG_LTC_OUTLINE_VERTICES);
  float step0 = 2.0 * o.span0 / float(LG_LTC_ARC_SEGMENTS), step1 = 2.0 * o.span1 / float(LG_LTC_ARC_SEGMENTS);
  vec2 step_ = o.round_ ? vec2(cos(round_step), sin(round_step)) : vec2(cos(step0), sin(step0));
  vec2 end1_step = vec2(cos(step1), sin(step1));
  vec2 end1_start = vec2(cos(o.span1), -sin(o.span1));
  // The last corner: a round outline's at pi / 2 - its step, a capsule's end 1's at span1.
  vec3 previous = o.round_ ? ltc_outline_point(o, false, step_.yx, 1.0)
                           : ltc_outline_point(o, true, end1_start * vec2(1.0, -1.0), 1.0);
  vec2 cs = o.round_ ? vec2(0.0, 1.0) : vec2(-cos(o.span0), sin(o.span0));
  // A do-while: a `for` that lavapipe does not unroll runs one more body, every lane masked off.
  int j = 0;
  do {
    bool on_end1 = !o.round_ && j > LG_LTC_ARC_SEGMENTS;
    int i = on_end1 ? j - (LG_LTC_ARC_SEGMENTS + 1) : j;
    bool arc_end = i == 0 || i == LG_LTC_ARC_SEGMENTS;
    float corner_radius = o.round_ || arc_end ? 1.0 : (on_end1 ? o.inner1 : o.inner0);
    vec3 next = ltc_outline_point(o, on_end1, cs, corner_radius);
    ltc_add_edge(poly, previous, next);
    previous = next;
    bool to_end1 = !o.round_ && j == LG_LTC_ARC_SEGMENTS;
    step_ = to_end1 ? end1_step : step_;
    cs = to_end1 ? end1_start : vec2(cs.x * step_.x - cs.y * step_.y, cs.y * step_.x + cs.x * step_.y);
  } while (++j < LG_LTC_OUTLINE_VERTICES);
  ltc_finish(poly);
  return ltc_form_factor(poly);
}

// The elliptical cone M^-1 makes of a sphere's cone, as area_light_ltc.cpp's ltc_cone_form_factor
// (which derives it): its axis and vector form factor F from the one negative eigenvalue of
// P = A J A^T; F, and true where the cone is wholly above the cosine's horizon (exact there).
bool ltc_cone_form_factor(vec3 c, float radius, mat3 to_cosine, out vec3 form_factor) {
  float d2 = dot(c, c);
  float tan_a = radius / sqrt(max(d2 - radius * radius, 1e-6 * d2));
  vec3 w = c / sqrt(d2);
  vec3 e1 = ltc_any_perpendicular(w), e2 = cross(w, e1);
  vec3 centre = to_cosine * w;
  float scale = 1.0 / length(centre);
  vec3 axis0 = centre * scale, v1 = to_cosine * e1 * (tan_a * scale), v2 = to_cosine * e2 * (tan_a * scale);
  mat3 pm = outerProduct(v1, v1) + outerProduct(v2, v2) - outerProduct(axis0, axis0);
  float mean = (pm[0][0] + pm[1][1] + pm[2][2]) / 3.0;
  float off = pm[1][0] * pm[1][0] + pm[2][0] * pm[2][0] + pm[2][1] * pm[2][1];
  vec3 diag = vec3(pm[0][0], pm[1][1], pm[2][2]) - mean;
  float spread = sqrt(max((dot(diag, diag) + 2.0 * off) / 6.0, 1e-30));
  float half_det = clamp(0.5 * determinant((pm - mat3(mean)) / spread), -1.0, 1.0);
  float p3 = mean + 2.0 * spread * cos(acos(half_det) / 3.0 + 2.0 * LG_PI / 3.0);
  mat3 shifted = pm - mat3(p3);
  vec3 c01 = cross(shifted[0], shifted[1]), c02 = cross(shifted[0], shifted[2]), c12 = cross(shifted[1], shifted[2]);
  float l01 = dot(c01, c01), l02 = dot(c02, c02), l12 = dot(c12, c12);
  vec3 axis = l01 > l02 ? (l01 > l12 ? c01 : c12) : (l02 > l12 ? c02 : c12);
  vec3 axis_dir = normalize(dot(axis, axis0) < 0.0 ? -axis : axis);
  float det_a = dot(v1, cross(v2, axis0));
  float minors = pm[0][0] * pm[1][1] + pm[0][0] * pm[2][2] + pm[1][1] * pm[2][2] - off;
  float slope = 3.0 * p3 * p3 - 6.0 * mean * p3 + minors;
  form_factor = clamp(abs(det_a) / sqrt(max(-p3 * slope, 1e-30)), 0.0, 1.0) * axis_dir;
  float adj00 = pm[1][1] * pm[2][2] - pm[1][2] * pm[1][2], adj11 = pm[0][0] * pm[2][2] - pm[0][2] * pm[0][2];
  float adj01 = pm[0][2] * pm[1][2] - pm[0][1] * pm[2][2];
  return adj00 < 0.0 && adj00 * adj11 > adj01 * adj01 && axis_dir.z > 0.0;
}

// I scaled by the exact lobe over the LTC at F's direction, weighed by exp(-5 |F|), as
// area_light_ltc.cpp's ltc_shape_corrected (which states why): in the frame of n and v, F's
// direction o carried back by M (M^-1's adjugate m, up to the sign of its determinant), the
// LTC's density there and the lobe's f (n.l) / E.
float ltc_shape_corrected(vec3 form_factor, LtcLobe lobe) {
  vec4 e = lobe.entry;
  float det = e.x * e.w - e.y * e.z;
  float f_len = length(form_factor);
  vec3 o = form_factor / f_len;
  vec3 m = vec3(e.w * o.x - e.y * o.z, det * o.y, e.x * o.z - e.z * o.x);
  float m_len = length(m);
  vec3 l = m * ((det < 0.0 ? -1.0 : 1.0) / m_len);
  float ltc = o.z / LG_PI * m_len * m_len * m_len / (det * det);
  float n_dot_v = max(lobe.view.z, 1e-4);
  vec3 h = normalize(l + lobe.view);
  float lobe_value = l.z > 0.0 ? ggx_distribution(h.z, lobe.alpha) * smith_visibility(n_dot_v, l.z, lobe.alpha) * l.z / lobe.albedo : 0.0;
  float ratio = lobe_value / ltc;
  ratio = ltc > 0.0 && !isinf(ratio) && !isnan(ratio) ? ratio : 1.0;
  float weight = exp(-5.0 * f_len);
  return form_factor.z * (weight * ratio + (1.0 - weight));
}

// A capsule (a = b for a sphere) as area_light_ltc.cpp's capsule_specular: seen from within its
// cylinder's reach the nearer end's sphere; a sphere (may_cone, a constant: tubes leave the cone
// out of their code) wholly above the surface's horizon whose elliptical cone is wholly above the
// cosine's that cone; anything else the outline polygon.
float ltc_capsule_specular(vec3 a, vec3 b, float radius, vec3 n, vec3 v, LtcLobe lobe, bool may_cone) {
  vec3 axis = b - a;
  float len = length(axis);
  vec3 dir = len > 0.0 ? axis / len : vec3(0.0);
  bool end_on = !(len > 0.0) || !(length(a - dir * dot(a, dir)) > radius);
  vec3 near_ = dot(a, a) < dot(b, b) ? a : b;
  bool cone = may_cone && end_on && radius > 0.0 && dot(normalize(n), near_) >= radius;
  vec3 f = vec3(0.0);
  bool exact = false;
  if (cone) exact = ltc_cone_form_factor(near_, radius, ltc_to_cosine(n, v, lobe.entry), f);
  if (!exact) f = ltc_capsule_form_factor(end_on ? near_ : a, end_on ? near_ : b, radius, n, v, lobe.entry);
  return f.z > 0.0 ? ltc_shape_corrected(f, lobe) : 0.0;
}

float ltc_sphere_specular(vec3 center, float radius, vec3 p, vec3 n, vec3 v, LtcLobe lobe) {
  vec3 c = center - p;
  return ltc_specular_result(ltc_capsule_specular(c, c, radius, n, v, lobe, true));
}

float ltc_tube_specular(vec3 end0, vec3 end1, float radius, vec3 p, vec3 n, vec3 v, LtcLobe lobe) {
  return ltc_specular_result(ltc_capsule_specular(end0 - p, end1 - p, radius, n, v, lobe, false));
}

float ltc_rect_specular(vec3 center, vec3 hx, vec3 hy, bool two_sided, vec3 p, vec3 n, vec3 v, LtcLobe lobe) {
  vec3 c = center - p;
  vec3 normal = cross(hx, hy);
  if (!two_sided && !(dot(c, normal) < 0.0)) return 0.0;
  LtcPolygon poly = ltc_polygon(n, v, lobe.entry);
  vec3 c0 = c - hx - hy, c1 = c + hx - hy, c2 = c + hx + hy, c3 = c - hx + hy;
  ltc_add_edge(poly, c0, c1);
  ltc_add_edge(poly, c1, c2);
  ltc_add_edge(poly, c2, c3);
  ltc_add_edge(poly, c3, c0);
  ltc_finish(poly);
  vec3 f = ltc_form_factor(poly);
  return ltc_specular_result(f.z > 0.0 ? ltc_shape_corrected(f, lobe) : 0.0);
}

#endif
