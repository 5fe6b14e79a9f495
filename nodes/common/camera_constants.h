// The camera block every pass binds (nodes/common/shaders/camera.glsl, std140), made from the
// scene's camera for a target of a given size. view_projection and its inverse carry the camera's
// sub-pixel jitter (runtime/scene/camera_jitter.h), previous_view_projection never does.
#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "runtime/scene/scene_view.h"

namespace lg {

struct CameraConstants {
  glm::mat4 view_projection;
  glm::mat4 inverse_view_projection;
  glm::mat4 previous_view_projection;
  glm::vec4 position;
  glm::vec4 viewport;  // width, height, 1 / width, 1 / height
  glm::vec4 jitter{0.0f};  // xy: the sub-pixel offset in view_projection, in NDC (0 when none); zw: 0
};

CameraConstants camera_constants(const CameraView& camera, uint32_t width, uint32_t height);

}  // namespace lg
