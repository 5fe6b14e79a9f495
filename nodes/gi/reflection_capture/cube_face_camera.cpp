#include "nodes/gi/reflection_capture/cube_face_camera.h"

#include <glm/matrix.hpp>

#include "nodes/env/common/cube_map.h"

namespace lg {

CameraConstants cube_face_camera(glm::vec3 position, int face, uint32_t size, float near_plane) {
  // cube_direction(face, u, v) is along axis + (2u - 1) s + (2v - 1) t with orthonormal axis, s
  // and t: for d = p - position, clip (d.s, d.t, near, d.axis) gives NDC (2u - 1, 2v - 1) and
  // depth near / distance along the axis.
  const glm::dvec3 axis = cube_direction(face, 0.5, 0.5);
  auto along = [&](double u, double v) {  // scaled to meet the plane at distance 1 on the axis
    const glm::dvec3 d = cube_direction(face, u, v);
    return d / glm::dot(d, axis) - axis;
  };
  const glm::vec3 s(along(1.0, 0.5)), t(along(0.5, 1.0)), a(axis);
  glm::mat4 clip(0.0f);  // columns
  for (int c = 0; c < 3; ++c) {
    clip[c][0] = s[c];
    clip[c][1] = t[c];
    clip[c][3] = a[c];
  }
  clip[3] = glm::vec4(-glm::dot(s, position), -glm::dot(t, position), near_plane, -glm::dot(a, position));
  CameraConstants camera;
  camera.view_projection = clip;
  camera.inverse_view_projection = glm::inverse(clip);
  camera.previous_view_projection = clip;
  camera.position = glm::vec4(position, 1.0f);
  camera.viewport = glm::vec4(float(size), float(size), 1.0f / float(size), 1.0f / float(size));
  return camera;
}

}  // namespace lg
