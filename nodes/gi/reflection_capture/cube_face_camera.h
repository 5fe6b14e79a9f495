// The camera that rasterizes one face of a cube map at a point: 90 degrees, reversed Z with an
// infinite far plane like the frame's (runtime/scene/projection.h), and texel (i, j) of the face
// seeing exactly cube_direction(face, (i + 0.5) / N, (j + 0.5) / N) (nodes/env/common/cube_map.h),
// so the faces drawn are a cube the env nodes read. The cube's faces are mirror images of a
// right-handed camera's view: front faces wind clockwise in them.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>

#include "nodes/common/camera_constants.h"

namespace lg {

CameraConstants cube_face_camera(glm::vec3 position, int face, uint32_t size, float near_plane);

}  // namespace lg
