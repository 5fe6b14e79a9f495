#include "runtime/scene/projection.h"

#include <cmath>

namespace lg {

glm::mat4 reversed_z_infinite_perspective(float vertical_fov, float aspect, float near_plane) {
  float f = 1.0f / std::tan(vertical_fov * 0.5f);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = -f;          // Vulkan's clip y points down
  p[2][3] = -1.0f;       // w = -z, the distance in front of the camera
  p[3][2] = near_plane;  // z = near, so depth = z / w = near / distance
  return p;
}

}  // namespace lg
