// The rasterizer's pixel geometry in double precision, so CPU references see each pixel where
// the G-buffer does: pixel (x, y)'s centre is at ((x + 0.5) / width, (y + 0.5) / height) of
// the image, rows top down, mapped through the inverse of the camera's own projection
// (runtime/scene/projection.h: Vulkan clip space, y down, reversed Z with an infinite far
// plane, device depth = near / distance).
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

class CameraPixels {
 public:
  CameraPixels(const CameraView& camera, uint32_t width, uint32_t height);

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  glm::dvec3 eye() const { return eye_; }
  // World-space unit direction of the primary ray through pixel (x, y)'s centre.
  glm::dvec3 ray_direction(uint32_t x, uint32_t y) const;
  // The view-space point at continuous pixel coordinates (px, py) (pixel centres at + 0.5) with
  // device depth `depth` (> 0).
  glm::dvec3 view_position(double px, double py, double depth) const;
  // View space to continuous pixel coordinates (x, y) and device depth (z); w > 0 in front.
  glm::dvec4 project(glm::dvec3 view_point) const;
  const glm::dmat4& view_from_world() const { return view_; }
  const glm::dmat4& world_from_view() const { return world_from_view_; }
  double near_plane() const { return near_; }

 private:
  uint32_t width_, height_;
  glm::dmat4 view_, world_from_view_, projection_, view_from_clip_;
  glm::dvec3 eye_;
  double near_;
};

}  // namespace lg
