// Area-light specular by linearly transformed cosines: the GLSL twin of area_light_ltc.cpp (which
// states the method). Each returns I, the fraction of the GGX lobe's energy the light covers (the
// caller multiplies by the radiance); the frame, ltc_frame(n, v, ltc_lookup(n.v, roughness))
// (ltc_table.glsl), is made once a pixel for all its lights.
#ifndef LG_AREA_LIGHT_LTC_GLSL
#define LG_AREA_LIGHT_LTC_GLSL

#include "nodes/lighting/deferred/shaders/area_light_math.glsl"

const int LG_LTC_ARC_SEGMENTS = 4;
const int LG_LTC_OUTLINE_VERTICES = 2 * (LG_LTC_ARC_SEGMENTS + 1);

vec3 ltc_any_perpendicular(vec3 n) {
  return normalize(cross(n, abs(n.x) < 0.7 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
}

float ltc_specular_result(float integral) {
  return clamp(finite_or_zero(integral), 0.0, 1.0);
}

// The Lambert formula's term of the edge between unit vectors a and b.
float ltc_edge_term(vec3 a, vec3 b) {
  vec3 c = cross(a, b);
  float s = length(c);
  return s > 0.0 ? c.z * atan(s, dot(a, b)) / s : 0.0;
}

// Where the great arc a-b crosses the plane through the origin (da, db: a's and b's distances
// along its normal, of opposite signs), as a unit vector.
vec3 ltc_crossing(vec3 a, vec3 b, float da, float db) {
  return normalize(a + (b - a) * (da / (da - db)));
}

struct LtcFrame {
  vec3 n;
  mat3 to_cosine;
  vec3 horizon;
};

LtcFrame ltc_frame(vec3 n, vec3 v, vec4 e) {
  n = normalize(n);
  vec3 t1 = v - n * dot(n, v);
  float len = length(t1);
  t1 = len > 1e-6 ? t1 / len : ltc_any_perpendicular(n);
  vec3 t2 = cross(n, t1);
  mat3 m_inv = mat3(vec3(e.x, 0.0, e.z), vec3(0.0, 1.0, 0.0), vec3(e.y, 0.0, e.w));
  // M^-1 maps the frame's (x, z) by [e.x e.y; e.z e.w], so the frame's z is
  // (e.x y.z - e.z y.x) / det: the surface's horizon, a plane in the cosine's space (its scale is
  // free: only signs and ratios of distances to it are used).
  float det = e.x * e.w - e.y * e.z;
  return LtcFrame(n, m_inv * transpose(mat3(t1, t2, n)), vec3(-e.z, 0.0, e.x) * det);
}

// A polygon's vertex relative to the shaded point, carried into the cosine's space.
vec3 ltc_direction(LtcFrame f, vec3 x) {
  return normalize(f.to_cosine * x);
}

struct LtcClip {
  float sum;
  vec3 exit_;
  vec3 entry;
  bool exited;
  bool entered;
};

struct LtcPolygon {
  vec3 horizon;
  LtcClip surface;
  LtcClip cosine;
};

LtcPolygon ltc_polygon(LtcFrame f) {
  LtcClip none = LtcClip(0.0, vec3(0.0), vec3(0.0), false, false);
  return LtcPolygon(f.horizon, none, none);
}

void ltc_add_cosine_edge(inout LtcClip c, vec3 a, vec3 b) {
  if (a.z > 0.0 && b.z > 0.0) {
    c.sum += ltc_edge_term(a, b);
  } else if (a.z > 0.0) {
    c.exit_ = ltc_crossing(a, b, a.z, b.z);
    c.exited = true;
    c.sum += ltc_edge_term(a, c.exit_);
  } else if (b.z > 0.0) {
    c.entry = ltc_crossing(a, b, a.z, b.z);
    c.entered = true;
    c.sum += ltc_edge_term(c.entry, b);
  }
}

// Edge a-b, both from ltc_direction: clipped to the surface's horizon, then to the cosine's.
void ltc_add_edge(inout LtcPolygon poly, vec3 a, vec3 b) {
  float da = dot(poly.horizon, a), db = dot(poly.horizon, b);
  if (da > 0.0 && db > 0.0) {
    ltc_add_cosine_edge(poly.cosine, a, b);
  } else if (da > 0.0) {
    poly.surface.exit_ = ltc_crossing(a, b, da, db);
    poly.surface.exited = true;
    ltc_add_cosine_edge(poly.cosine, a, poly.surface.exit_);
  } else if (db > 0.0) {
    poly.surface.entry = ltc_crossing(a, b, da, db);
    poly.surface.entered = true;
    ltc_add_cosine_edge(poly.cosine, poly.surface.entry, b);
  }
}

float ltc_finish(inout LtcPolygon poly) {
  if (poly.surface.exited && poly.surface.entered)
    ltc_add_cosine_edge(poly.cosine, poly.surface.exit_, poly.surface.entry);
  if (poly.cosine.exited && poly.cosine.entered) poly.cosine.sum += ltc_edge_term(poly.cosine.exit_, poly.cosine.entry);
  return abs(poly.cosine.sum) / (2.0 * LG_PI);
}

struct LtcOutline {
  vec3 end0;
  vec3 end1;
  float radius0;
  float radius1;
  vec3 along;
  vec3 side;
};

bool ltc_capsule_outline(vec3 a, vec3 b, float radius, vec3 n, out LtcOutline o) {
  o = LtcOutline(a, b, 0.0, 0.0, vec3(0.0), vec3(0.0));
  vec3 c = 0.5 * (a + b);
  float dc = length(c);
  if (!(dc > 0.0) || !(radius > 0.0)) return false;
  vec3 u = c / dc;
  float segments = float(LG_LTC_ARC_SEGMENTS);
  float grow = sqrt(LG_PI / (segments * sin(LG_PI / segments)));
  float depth = max(dot(a, u), 1e-3 * dc);
  float scale = dc / depth;
  o.end0 = a * scale + u * (dc - dot(a, u) * scale);
  float d2 = dot(a, a);
  o.radius0 = radius * sqrt(d2) * scale / sqrt(max(d2 - radius * radius, 1e-6 * d2)) * grow;
  depth = max(dot(b, u), 1e-3 * dc);
  scale = dc / depth;
  o.end1 = b * scale + u * (dc - dot(b, u) * scale);
  d2 = dot(b, b);
  o.radius1 = radius * sqrt(d2) * scale / sqrt(max(d2 - radius * radius, 1e-6 * d2)) * grow;
  vec3 axis = o.end1 - o.end0;
  float len = length(axis);
  if (len > 1e-6 * dc) {
    o.along = axis / len;
  } else {
    vec3 in_plane = n - u * dot(n, u);
    o.along = length(in_plane) > 1e-6 ? normalize(in_plane) : ltc_any_perpendicular(u);
  }
  o.side = cross(u, o.along);
  return true;
}

// (cos, sin) of pi / 2 + pi k / LG_LTC_ARC_SEGMENTS: end 0's half circle (end 1's is its negative).
const vec2 LG_LTC_ARC[LG_LTC_ARC_SEGMENTS + 1] =
    vec2[](vec2(0.0, 1.0), vec2(-0.70710678, 0.70710678), vec2(-1.0, 0.0), vec2(-0.70710678, -0.70710678), vec2(0.0, -1.0));

vec3 ltc_outline_vertex(LtcOutline o, int j) {
  int half_ = j / (LG_LTC_ARC_SEGMENTS + 1);
  vec2 arc = LG_LTC_ARC[j - half_ * (LG_LTC_ARC_SEGMENTS + 1)];
  vec3 offset = arc.x * o.along + arc.y * o.side;
  return half_ == 0 ? o.end0 + o.radius0 * offset : o.end1 - o.radius1 * offset;
}

float ltc_capsule_integral(vec3 a, vec3 b, float radius, LtcFrame f) {
  LtcOutline o;
  if (!ltc_capsule_outline(a, b, radius, f.n, o)) return 0.0;
  LtcPolygon poly = ltc_polygon(f);
  vec3 previous = ltc_direction(f, ltc_outline_vertex(o, LG_LTC_OUTLINE_VERTICES - 1));
  for (int j = 0; j < LG_LTC_OUTLINE_VERTICES; ++j) {
    vec3 next = ltc_direction(f, ltc_outline_vertex(o, j));
    ltc_add_edge(poly, previous, next);
    previous = next;
  }
  return ltc_finish(poly);
}

float ltc_sphere_specular(vec3 center, float radius, vec3 p, LtcFrame f) {
  vec3 c = center - p;
  return ltc_specular_result(ltc_capsule_integral(c, c, radius, f));
}

float ltc_tube_specular(vec3 end0, vec3 end1, float radius, vec3 p, LtcFrame f) {
  return ltc_specular_result(ltc_capsule_integral(end0 - p, end1 - p, radius, f));
}

float ltc_rect_specular(vec3 center, vec3 hx, vec3 hy, bool two_sided, vec3 p, LtcFrame f) {
  vec3 c = center - p;
  vec3 normal = cross(hx, hy);
  if (!two_sided && !(dot(c, normal) < 0.0)) return 0.0;
  LtcPolygon poly = ltc_polygon(f);
  vec3 c0 = ltc_direction(f, c - hx - hy), c1 = ltc_direction(f, c + hx - hy);
  vec3 c2 = ltc_direction(f, c + hx + hy), c3 = ltc_direction(f, c - hx + hy);
  ltc_add_edge(poly, c0, c1);
  ltc_add_edge(poly, c1, c2);
  ltc_add_edge(poly, c2, c3);
  ltc_add_edge(poly, c3, c0);
  return ltc_specular_result(ltc_finish(poly));
}

#endif
