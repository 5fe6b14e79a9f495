// Representative-point specular for area lights (Karis 2013): the GLSL twin of
// area_light_specular.cpp. Shade the returned point as a point light of the area light's
// intensity and multiply by `normalization`.
#ifndef LG_AREA_LIGHT_SPECULAR_GLSL
#define LG_AREA_LIGHT_SPECULAR_GLSL

#include "nodes/lighting/deferred/shaders/area_light_math.glsl"

const float LG_MIN_SPECULAR_ALPHA = 1e-4;

struct RepresentativePoint {
  vec3 direction;
  float distance;
  float normalization;
};

RepresentativePoint make_point(vec3 to_point, float normalization) {
  float dist = length(to_point);
  vec3 dir = to_point / dist;
  bool usable = dist > 0.0 && is_finite(dist) && is_finite(dir.x) && is_finite(dir.y) && is_finite(dir.z) &&
                is_finite(normalization);
  if (!usable) return RepresentativePoint(vec3(0.0), 0.0, 0.0);
  return RepresentativePoint(dir, dist, clamp(normalization, 0.0, 1.0));
}

float clamp_alpha(float alpha) {
  return clamp(alpha, LG_MIN_SPECULAR_ALPHA, 1.0);
}

float widening(float alpha, float angle) {
  return alpha / clamp(alpha + angle, 0.0, 1.0);
}

vec3 sphere_point(vec3 center, float radius, vec3 reflection) {
  vec3 to_ray = dot(center, reflection) * reflection - center;
  float gap = length(to_ray);
  return center + to_ray * (gap > 0.0 ? clamp(radius / gap, 0.0, 1.0) : 0.0);
}

RepresentativePoint sphere_specular_point(vec3 light_center, float radius, vec3 p, vec3 reflection, float alpha) {
  alpha = clamp_alpha(alpha);
  vec3 center = light_center - p;
  float ratio = widening(alpha, radius / (2.0 * length(center)));
  return make_point(sphere_point(center, radius, reflection), ratio * ratio);
}

RepresentativePoint tube_specular_point(vec3 end0, vec3 end1, float radius, vec3 p, vec3 reflection, float alpha) {
  alpha = clamp_alpha(alpha);
  vec3 a = end0 - p;
  vec3 d = end1 - end0;
  float dd = dot(d, d);
  float rd = dot(reflection, d);
  float denom = dd - rd * rd;
  float t = 0.0;
  if (denom > 1e-6 * dd) {
    t = (dot(reflection, a) * rd - dot(a, d)) / denom;
  } else if (dd > 0.0) {
    t = -dot(a, d) / dd;
  }
  vec3 center = a + clamp(t, 0.0, 1.0) * d;
  float dist = length(center);
  float ratio = widening(alpha, radius / (2.0 * dist));
  float line = widening(alpha, sqrt(dd) / (4.0 * dist));
  return make_point(sphere_point(center, radius, reflection), ratio * ratio * line);
}

RepresentativePoint rect_specular_point(vec3 center, vec3 hx, vec3 hy, bool two_sided, vec3 p, vec3 reflection,
                                        float alpha) {
  alpha = clamp_alpha(alpha);
  vec3 c = center - p;
  vec3 normal = cross(hx, hy);
  float cn = dot(c, normal);
  if (!two_sided && !(cn < 0.0)) return RepresentativePoint(vec3(0.0), 0.0, 0.0);
  float dist = length(c);
  float rn = dot(reflection, normal);
  vec3 hit;
  if (rn * cn > 0.0) {
    hit = min(cn / rn, 1e4 * dist) * reflection;
  } else {
    hit = dist * reflection;
    hit -= dot(hit - c, normal) / dot(normal, normal) * normal;
  }
  vec3 local = hit - c;
  float xx = dot(hx, hx);
  float yy = dot(hy, hy);
  float u = xx > 0.0 ? clamp(dot(local, hx) / xx, -1.0, 1.0) : 0.0;
  float v = yy > 0.0 ? clamp(dot(local, hy) / yy, -1.0, 1.0) : 0.0;
  float norm = widening(alpha, sqrt(xx) / (2.0 * dist)) * widening(alpha, sqrt(yy) / (2.0 * dist));
  return make_point(c + u * hx + v * hy, norm);
}

#endif
