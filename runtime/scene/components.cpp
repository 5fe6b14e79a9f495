#include "runtime/scene/components.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace lg {

glm::mat4 Transform::local_matrix() const {
  glm::mat4 m = glm::mat4_cast(rotation);
  m[0] *= scale.x;
  m[1] *= scale.y;
  m[2] *= scale.z;
  m[3] = glm::vec4(position, 1.0f);
  return m;
}

glm::quat look_rotation(glm::vec3 direction, glm::vec3 up) {
  glm::vec3 d = glm::normalize(direction);
  // Looking straight along `up` leaves the roll free: take another up.
  if (std::abs(glm::dot(d, glm::normalize(up))) > 0.9999f)
    up = std::abs(d.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  return glm::quatLookAtRH(d, up);
}

}  // namespace lg
