// Camera matrices in Vulkan's clip space with reversed Z and an infinite far plane: depth is
// near/distance, 1 at the near plane and falling to 0 at infinity; clip y points down.
#pragma once

#include <glm/mat4x4.hpp>

namespace lg {

// Right-handed view space looking down -Z. vertical_fov in radians, aspect = width / height.
glm::mat4 reversed_z_infinite_perspective(float vertical_fov, float aspect, float near_plane);

}  // namespace lg
