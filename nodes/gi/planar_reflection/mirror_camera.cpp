#include "nodes/gi/planar_reflection/mirror_camera.h"

namespace lg {

glm::mat4 mirror_matrix(const glm::vec4& plane) {
  const glm::vec3 n(plane);
  glm::mat4 m(1.0f);
  for (int column = 0; column < 3; ++column)
    for (int row = 0; row < 3; ++row) m[column][row] -= 2.0f * n[row] * n[column];
  m[3] = glm::vec4(-2.0f * plane.w * n, 1.0f);
  return m;
}

CameraConstants mirrored_camera(const CameraView& camera, const glm::vec4& plane, uint32_t width, uint32_t height) {
  const glm::mat4 mirror = mirror_matrix(plane);
  CameraView mirrored = camera;
  mirrored.view = camera.view * mirror;
  mirrored.position = glm::vec3(mirror * glm::vec4(camera.position, 1.0f));
  CameraConstants constants = camera_constants(mirrored, width, height);
  constants.previous_view_projection = constants.view_projection;
  return constants;
}

}  // namespace lg
