#include "nodes/lighting/deferred/area_light_ltc.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "nodes/lighting/deferred/area_light_math.h"
#include "nodes/lighting/deferred/ltc_table.h"

namespace lg {
namespace {

using glm::vec3;

vec3 any_perpendicular(vec3 n) {
  return glm::normalize(glm::cross(n, std::fabs(n.x) < 0.7f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
}

float specular_result(float radiance, float integral) {
  return finite_or_zero(std::max(radiance, 0.0f) * clamp01(finite_or_zero(integral)));
}

}  // namespace

glm::mat3 ltc_to_cosine(vec3 n, vec3 v, glm::vec4 entry) {
  n = glm::normalize(n);
  vec3 t1 = v - n * glm::dot(n, v);
  const float len = glm::length(t1);
  // Seen straight on, any tangent serves: the lobe is round there.
  t1 = len > 1e-6f ? t1 / len : any_perpendicular(n);
  const vec3 t2 = glm::cross(n, t1);
  return ltc_inverse(entry) * glm::transpose(glm::mat3(t1, t2, n));
}

namespace {

// Sutherland-Hodgman against the plane through the origin with normal m: each edge keeps its
// start if in front and adds its crossing. Returns the count kept (at most count + 1 for a convex
// polygon).
int clip_in_front(const vec3* in, int count, vec3 m, vec3* out) {
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    const vec3 a = in[i], b = in[(i + 1) % count];
    const float da = glm::dot(m, a), db = glm::dot(m, b);
    if (da > 0.0f) out[kept++] = a;
    if ((da > 0.0f) != (db > 0.0f)) out[kept++] = a + (b - a) * (da / (da - db));
  }
  return kept;
}

}  // namespace

float ltc_polygon_integral(const vec3* vertices, int count, vec3 n, const glm::mat3& to_cosine) {
  // Above the surface's horizon (the lobe is 0 below it; the cosine it is fitted with is not
  // quite), then into the cosine's space and above its horizon.
  vec3 above[kLtcMaxVertices], cosine[kLtcMaxVertices];
  const int n_above = clip_in_front(vertices, count, n, above);
  for (int i = 0; i < n_above; ++i) above[i] = to_cosine * above[i];
  const int n_kept = clip_in_front(above, n_above, vec3(0.0f, 0.0f, 1.0f), cosine);
  // The Lambert polygon formula: (1 / 2 pi) |sum over edges of angle x the z of their unit normal|.
  float sum = 0.0f;
  for (int i = 0; i < n_kept; ++i) {
    const vec3 e0 = glm::normalize(cosine[i]);
    const vec3 e1 = glm::normalize(cosine[(i + 1) % n_kept]);
    const vec3 c = glm::cross(e0, e1);
    const float s = glm::length(c);
    // atan2 keeps the angle exact for short edges, where acos of the dot product loses it.
    if (s > 0.0f) sum += c.z * std::atan2(s, glm::dot(e0, e1)) / s;
  }
  return std::fabs(sum) / (2.0f * kAreaLightPi);
}

int ltc_capsule_outline(vec3 a, vec3 b, float radius, vec3 n, vec3* vertices) {
  const vec3 c = 0.5f * (a + b);
  const float dc = glm::length(c);
  if (!(dc > 0.0f) || !(radius > 0.0f)) return 0;
  const vec3 u = c / dc;
  vec3 ends[2] = {a, b};
  float radii[2];
  for (int k = 0; k < 2; ++k) {
    const vec3 e = ends[k];
    // Along the ray to the end, onto the plane (an end beside or behind the point is held in front).
    const float depth = std::max(glm::dot(e, u), 1e-3f * dc);
    const float scale = dc / depth;
    ends[k] = e * scale + u * (dc - glm::dot(e, u) * scale);
    // Its sphere's cone has tan = r / sqrt(d^2 - r^2) (held finite inside the sphere).
    const float d2 = glm::dot(e, e);
    radii[k] = radius * std::sqrt(d2) * scale / std::sqrt(std::max(d2 - radius * radius, 1e-6f * d2));
  }
  const vec3 axis = ends[1] - ends[0];
  const float len = glm::length(axis);
  vec3 along;
  if (len > 1e-6f * dc) {
    along = axis / len;
  } else {
    // A sphere, or a capsule seen end on: its outline is round; one half polygon's edge lies
    // along the horizon's trace for symmetry.
    const vec3 in_plane = n - u * glm::dot(n, u);
    along = glm::length(in_plane) > 1e-6f ? glm::normalize(in_plane) : any_perpendicular(u);
  }
  const vec3 side = glm::cross(u, along);
  const float segments = float(kLtcArcSegments);
  // A half polygon of k segments inscribed in radius R has area k R^2 sin(pi / k) / 2.
  const float grow = std::sqrt(kAreaLightPi / (segments * std::sin(kAreaLightPi / segments)));
  int count = 0;
  for (int half = 0; half < 2; ++half) {
    // End 0's half circle faces away from end 1 (through -along), end 1's through +along.
    const float start = half == 0 ? 0.5f * kAreaLightPi : -0.5f * kAreaLightPi;
    for (int j = 0; j <= kLtcArcSegments; ++j) {
      const float angle = start + kAreaLightPi * float(j) / segments;
      vertices[count++] = ends[half] + radii[half] * grow * (std::cos(angle) * along + std::sin(angle) * side);
    }
  }
  return count;
}

float ltc_sphere_specular(const SphereLight& light, vec3 p, vec3 n, vec3 v, glm::vec4 entry) {
  vec3 outline[kLtcMaxVertices];
  const vec3 c = light.center - p;
  const int count = ltc_capsule_outline(c, c, light.radius, n, outline);
  if (count == 0) return 0.0f;
  return specular_result(light.radiance, ltc_polygon_integral(outline, count, glm::normalize(n), ltc_to_cosine(n, v, entry)));
}

float ltc_tube_specular(const TubeLight& light, vec3 p, vec3 n, vec3 v, glm::vec4 entry) {
  vec3 outline[kLtcMaxVertices];
  const int count = ltc_capsule_outline(light.end0 - p, light.end1 - p, light.radius, n, outline);
  if (count == 0) return 0.0f;
  return specular_result(light.radiance, ltc_polygon_integral(outline, count, glm::normalize(n), ltc_to_cosine(n, v, entry)));
}

float ltc_rect_specular(const RectLight& light, vec3 p, vec3 n, vec3 v, glm::vec4 entry) {
  const vec3 c = light.center - p;
  const vec3 normal = glm::cross(light.half_x, light.half_y);
  // A one-sided light shines on points in front of it only; its plane holds none.
  if (!light.two_sided && !(glm::dot(c, normal) < 0.0f)) return 0.0f;
  const vec3 corners[4] = {c - light.half_x - light.half_y, c + light.half_x - light.half_y,
                           c + light.half_x + light.half_y, c - light.half_x + light.half_y};
  return specular_result(light.radiance, ltc_polygon_integral(corners, 4, glm::normalize(n), ltc_to_cosine(n, v, entry)));
}

}  // namespace lg
