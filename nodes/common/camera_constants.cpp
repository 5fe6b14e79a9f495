#include "nodes/common/camera_constants.h"

#include <glm/matrix.hpp>

#include "runtime/scene/camera_jitter.h"

namespace lg {

CameraConstants camera_constants(const CameraView& camera, uint32_t width, uint32_t height) {
  CameraConstants c;
  c.view_projection = jittered_projection(camera) * camera.view;
  c.inverse_view_projection = glm::inverse(c.view_projection);
  c.previous_view_projection = camera.previous_view_projection;
  c.position = glm::vec4(camera.position, 1.0f);
  c.viewport = glm::vec4(float(width), float(height), 1.0f / float(width), 1.0f / float(height));
  c.jitter = glm::vec4(camera.jitter.value_or(glm::vec2(0.0f)), 0.0f, 0.0f);
  return c;
}

}  // namespace lg
