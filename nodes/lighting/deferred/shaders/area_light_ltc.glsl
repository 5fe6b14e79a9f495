// Area-light specular by linearly transformed cosines: the GLSL twin of area_light_ltc.cpp (which
// states the method). Each returns I, the fraction of the GGX lobe's energy the light covers (the
// caller multiplies by the radiance); `entry` is ltc_lookup(n.v, roughness) (ltc_table.glsl).
#ifndef LG_AREA_LIGHT_LTC_GLSL
#define LG_AREA_LIGHT_LTC_GLSL

#include "nodes/lighting/deferred/shaders/area_light_math.glsl"

const int LG_LTC_ARC_SEGMENTS = 4;
const int LG_LTC_MAX_VERTICES = 16;

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

int ltc_clip_in_front(vec3 in_[LG_LTC_MAX_VERTICES], int count, vec3 m, out vec3 out_[LG_LTC_MAX_VERTICES]) {
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    vec3 a = in_[i], b = in_[(i + 1) % count];
    float da = dot(m, a), db = dot(m, b);
    if (da > 0.0) out_[kept++] = a;
    if ((da > 0.0) != (db > 0.0)) out_[kept++] = a + (b - a) * (da / (da - db));
  }
  return kept;
}

float ltc_polygon_integral(vec3 vertices[LG_LTC_MAX_VERTICES], int count, vec3 n, mat3 to_cosine) {
  vec3 above[LG_LTC_MAX_VERTICES], cosine[LG_LTC_MAX_VERTICES];
  int n_above = ltc_clip_in_front(vertices, count, n, above);
  for (int i = 0; i < n_above; ++i) above[i] = to_cosine * above[i];
  int n_kept = ltc_clip_in_front(above, n_above, vec3(0.0, 0.0, 1.0), cosine);
  float sum = 0.0;
  for (int i = 0; i < n_kept; ++i) {
    vec3 e0 = normalize(cosine[i]);
    vec3 e1 = normalize(cosine[(i + 1) % n_kept]);
    vec3 c = cross(e0, e1);
    float s = length(c);
    if (s > 0.0) sum += c.z * atan(s, dot(e0, e1)) / s;
  }
  return abs(sum) / (2.0 * LG_PI);
}

int ltc_capsule_outline(vec3 a, vec3 b, float radius, vec3 n, out vec3 vertices[LG_LTC_MAX_VERTICES]) {
  vec3 c = 0.5 * (a + b);
  float dc = length(c);
  if (!(dc > 0.0) || !(radius > 0.0)) return 0;
  vec3 u = c / dc;
  vec3 ends[2] = vec3[2](a, b);
  float radii[2];
  for (int k = 0; k < 2; ++k) {
    vec3 e = ends[k];
    float depth = max(dot(e, u), 1e-3 * dc);
    float scale = dc / depth;
    ends[k] = e * scale + u * (dc - dot(e, u) * scale);
    float d2 = dot(e, e);
    radii[k] = radius * sqrt(d2) * scale / sqrt(max(d2 - radius * radius, 1e-6 * d2));
  }
  vec3 axis = ends[1] - ends[0];
  float len = length(axis);
  vec3 along;
  if (len > 1e-6 * dc) {
    along = axis / len;
  } else {
    vec3 in_plane = n - u * dot(n, u);
    along = length(in_plane) > 1e-6 ? normalize(in_plane) : ltc_any_perpendicular(u);
  }
  vec3 side = cross(u, along);
  float segments = float(LG_LTC_ARC_SEGMENTS);
  float grow = sqrt(LG_PI / (segments * sin(LG_PI / segments)));
  int count = 0;
  for (int half_ = 0; half_ < 2; ++half_) {
    float start = half_ == 0 ? 0.5 * LG_PI : -0.5 * LG_PI;
    for (int j = 0; j <= LG_LTC_ARC_SEGMENTS; ++j) {
      float angle = start + LG_PI * float(j) / segments;
      vertices[count++] = ends[half_] + radii[half_] * grow * (cos(angle) * along + sin(angle) * side);
    }
  }
  return count;
}

float ltc_sphere_specular(vec3 center, float radius, vec3 p, vec3 n, vec3 v, vec4 entry) {
  vec3 outline[LG_LTC_MAX_VERTICES];
  vec3 c = center - p;
  int count = ltc_capsule_outline(c, c, radius, n, outline);
  if (count == 0) return 0.0;
  return ltc_specular_result(ltc_polygon_integral(outline, count, normalize(n), ltc_to_cosine(n, v, entry)));
}

float ltc_tube_specular(vec3 end0, vec3 end1, float radius, vec3 p, vec3 n, vec3 v, vec4 entry) {
  vec3 outline[LG_LTC_MAX_VERTICES];
  int count = ltc_capsule_outline(end0 - p, end1 - p, radius, n, outline);
  if (count == 0) return 0.0;
  return ltc_specular_result(ltc_polygon_integral(outline, count, normalize(n), ltc_to_cosine(n, v, entry)));
}

float ltc_rect_specular(vec3 center, vec3 hx, vec3 hy, bool two_sided, vec3 p, vec3 n, vec3 v, vec4 entry) {
  vec3 c = center - p;
  vec3 normal = cross(hx, hy);
  if (!two_sided && !(dot(c, normal) < 0.0)) return 0.0;
  vec3 corners[LG_LTC_MAX_VERTICES];
  corners[0] = c - hx - hy;
  corners[1] = c + hx - hy;
  corners[2] = c + hx + hy;
  corners[3] = c - hx + hy;
  return ltc_specular_result(ltc_polygon_integral(corners, 4, normalize(n), ltc_to_cosine(n, v, entry)));
}

#endif
