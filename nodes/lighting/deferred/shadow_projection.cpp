#include "nodes/lighting/deferred/shadow_projection.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lg {

Bounds scene_bounds(const SceneView& scene) {
  Bounds b;
  for (const DrawItem& d : scene.draws)
    for (const glm::vec3& p : scene.mesh_of(d).positions) b.add(glm::vec3(d.world * glm::vec4(p, 1.0f)));
  if (!(b.min.x <= b.max.x)) return {glm::vec3(-0.5f), glm::vec3(0.5f)};
  return b;
}

glm::mat4 shadow_from_world(const Bounds& bounds, glm::vec3 direction) {
  const glm::vec3 center = bounds.center();
  const float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 helper = std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 right = glm::normalize(glm::cross(helper, d));
  const glm::vec3 up = glm::cross(d, right);
  // Rows: x and y across the light's beam scaled to [-1, 1]; depth 0.5 - 0.5 w / radius with
  // w the distance along the beam from the center, so the bounding sphere spans [0, 1].
  auto row = [&](glm::mat4& m, int i, glm::vec3 axis, float scale, float offset) {
    m[0][i] = axis.x * scale;
    m[1][i] = axis.y * scale;
    m[2][i] = axis.z * scale;
    m[3][i] = offset - glm::dot(axis, center) * scale;
  };
  glm::mat4 m(1.0f);
  row(m, 0, right, 1.0f / radius, 0.0f);
  row(m, 1, up, 1.0f / radius, 0.0f);
  row(m, 2, d, -0.5f / radius, 0.5f);
  return m;
}

}  // namespace lg
