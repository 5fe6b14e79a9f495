// The surface a camera ray first meets, as the G-buffer sees it: with back-face culling the ray
// passes through faces of single-sided materials turned away from the camera (the pixel shows
// what lies behind them); a double-sided material's back face, or any back face without
// culling, is the visible surface, shaded on the camera's side. Alpha-tested surfaces let the ray
// through where RayScene says so.
#pragma once

#include <glm/vec3.hpp>
#include <optional>

#include "nodes/raytrace/ray_scene.h"

namespace lg {

struct CameraHit {
  RayHit hit;              // the triangle met (its distance is from the last culled face, not the eye)
  glm::dvec3 position;     // world space
  bool front_face = true;  // whether the camera sees the triangle's front (counter-clockwise) side
};

std::optional<CameraHit> first_camera_hit(const RayScene& scene, glm::dvec3 eye, glm::dvec3 direction,
                                          bool cull_backfaces);

}  // namespace lg
