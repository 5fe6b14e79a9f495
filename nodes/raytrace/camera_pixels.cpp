#include "nodes/raytrace/camera_pixels.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lg {

CameraPixels::CameraPixels(const CameraView& camera, uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      view_(glm::dmat4(camera.view)),
      world_from_view_(glm::inverse(view_)),
      projection_(glm::dmat4(camera.projection)),
      view_from_clip_(glm::inverse(projection_)),
      eye_(world_from_view_[3]),
      near_(camera.near_plane) {}

glm::dvec3 CameraPixels::view_position(double px, double py, double depth) const {
  const glm::dvec4 ndc(2.0 * px / width_ - 1.0, 2.0 * py / height_ - 1.0, depth, 1.0);
  const glm::dvec4 v = view_from_clip_ * ndc;
  return glm::dvec3(v) / v.w;
}

glm::dvec3 CameraPixels::ray_direction(uint32_t x, uint32_t y) const {
  // The point on the near plane (device depth 1) seen through the pixel centre.
  const glm::dvec3 on_near = view_position(x + 0.5, y + 0.5, 1.0);
  return glm::normalize(glm::dmat3(world_from_view_) * on_near);
}

glm::dvec4 CameraPixels::project(glm::dvec3 view_point) const {
  const glm::dvec4 clip = projection_ * glm::dvec4(view_point, 1.0);
  return {(clip.x / clip.w * 0.5 + 0.5) * width_, (clip.y / clip.w * 0.5 + 0.5) * height_, clip.z / clip.w, clip.w};
}

}  // namespace lg
