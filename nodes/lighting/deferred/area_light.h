// Sphere, tube and rectangle area lights as the real-time formulas see them (float, GLSL-like).
// Positions are in world units; radiance is the light's uniform Lambertian radiance (see README).
#pragma once

#include <glm/vec3.hpp>

namespace lg {

struct SphereLight {
  glm::vec3 center;
  float radius;
  float radiance;
};

// A capsule: every point within `radius` of the segment end0-end1 (a cylinder with two
// hemispherical caps).
struct TubeLight {
  glm::vec3 end0;
  glm::vec3 end1;
  float radius;
  float radiance;
};

// half_x and half_y are perpendicular; a one-sided light emits toward cross(half_x, half_y).
struct RectLight {
  glm::vec3 center;
  glm::vec3 half_x;
  glm::vec3 half_y;
  float radiance;
  bool two_sided;
};

}  // namespace lg
