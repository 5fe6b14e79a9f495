#include "nodes/lighting/deferred/area_light_specular.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/lighting/deferred/area_light_math.h"

namespace lg {
namespace {

// The direction to a point and its factor, or no contribution when either is not finite or
// the point is the shaded point itself.
RepresentativePoint make_point(glm::vec3 to_point, float normalization) {
  float dist = glm::length(to_point);
  glm::vec3 dir = to_point / dist;
  bool usable = dist > 0.0f && is_finite(dist) && is_finite(dir.x) && is_finite(dir.y) && is_finite(dir.z) &&
                is_finite(normalization);
  if (!usable) return RepresentativePoint{glm::vec3(0.0f), 0.0f, 0.0f};
  return RepresentativePoint{dir, dist, clamp01(normalization)};
}

float clamp_alpha(float alpha) {
  return std::fmin(std::fmax(alpha, kMinSpecularAlpha), 1.0f);
}

// alpha / alpha' for a lobe widened by `angle` (radians) in one direction.
float widening(float alpha, float angle) {
  return alpha / clamp01(alpha + angle);
}

// The point of the sphere at `center` (relative to p) closest to the reflection ray.
glm::vec3 sphere_point(glm::vec3 center, float radius, glm::vec3 reflection) {
  glm::vec3 to_ray = glm::dot(center, reflection) * reflection - center;
  float gap = glm::length(to_ray);
  return center + to_ray * (gap > 0.0f ? clamp01(radius / gap) : 0.0f);
}

}  // namespace

RepresentativePoint sphere_specular_point(const SphereLight& light, glm::vec3 p, glm::vec3 reflection, float alpha) {
  alpha = clamp_alpha(alpha);
  glm::vec3 center = light.center - p;
  float ratio = widening(alpha, light.radius / (2.0f * glm::length(center)));
  return make_point(sphere_point(center, light.radius, reflection), ratio * ratio);
}

RepresentativePoint tube_specular_point(const TubeLight& light, glm::vec3 p, glm::vec3 reflection, float alpha) {
  alpha = clamp_alpha(alpha);
  glm::vec3 a = light.end0 - p;
  glm::vec3 d = light.end1 - light.end0;
  float dd = glm::dot(d, d);
  float rd = glm::dot(reflection, d);
  float denom = dd - rd * rd;
  // The segment parameter closest to the reflection line; a line parallel to the segment is
  // equally close everywhere, so take the segment point nearest p.
  float t = 0.0f;
  if (denom > 1e-6f * dd) {
    t = (glm::dot(reflection, a) * rd - glm::dot(a, d)) / denom;
  } else if (dd > 0.0f) {
    t = -glm::dot(a, d) / dd;
  }
  glm::vec3 center = a + clamp01(t) * d;
  float dist = glm::length(center);
  float ratio = widening(alpha, light.radius / (2.0f * dist));
  float line = widening(alpha, std::sqrt(dd) / (4.0f * dist));
  return make_point(sphere_point(center, light.radius, reflection), ratio * ratio * line);
}

RepresentativePoint rect_specular_point(const RectLight& light, glm::vec3 p, glm::vec3 reflection, float alpha) {
  alpha = clamp_alpha(alpha);
  glm::vec3 c = light.center - p;
  glm::vec3 hx = light.half_x;
  glm::vec3 hy = light.half_y;
  glm::vec3 normal = glm::cross(hx, hy);
  float cn = glm::dot(c, normal);
  if (!light.two_sided && !(cn < 0.0f)) return RepresentativePoint{glm::vec3(0.0f), 0.0f, 0.0f};
  float dist = glm::length(c);
  float rn = glm::dot(reflection, normal);
  // Beyond 1e4 light distances the hit's direction no longer changes; the cap keeps it finite.
  glm::vec3 hit;
  if (rn * cn > 0.0f) {
    hit = std::fmin(cn / rn, 1e4f * dist) * reflection;
  } else {
    hit = dist * reflection;
    hit -= glm::dot(hit - c, normal) / glm::dot(normal, normal) * normal;
  }
  glm::vec3 local = hit - c;
  float xx = glm::dot(hx, hx);
  float yy = glm::dot(hy, hy);
  float u = xx > 0.0f ? std::fmin(std::fmax(glm::dot(local, hx) / xx, -1.0f), 1.0f) : 0.0f;
  float v = yy > 0.0f ? std::fmin(std::fmax(glm::dot(local, hy) / yy, -1.0f), 1.0f) : 0.0f;
  float norm = widening(alpha, std::sqrt(xx) / (2.0f * dist)) * widening(alpha, std::sqrt(yy) / (2.0f * dist));
  return make_point(c + u * hx + v * hy, norm);
}

}  // namespace lg
