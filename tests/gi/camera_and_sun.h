// A camera and a sun for the GI nodes' test worlds (gi.lpv carries the sun's bounce, and runs
// without one only for the sky; at intensity 0 it adds nothing, and what the test puts in lights
// the world).
#pragma once

#include <glm/vec3.hpp>

#include "runtime/scene/components.h"
#include "runtime/scene/world.h"

namespace lg::test {

// A camera at `eye` looking along `look`.
inline void add_camera(World& world, glm::vec3 eye, glm::vec3 look) {
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& t = world.add(camera, Transform{});
  t.position = eye;
  t.rotation = look_rotation(look);
}

// That camera, and a sun shining along `sun_direction`.
inline void add_camera_and_sun(World& world, glm::vec3 eye, glm::vec3 look, glm::vec3 sun_direction, float intensity) {
  add_camera(world, eye, look);
  Entity sun = world.create("sun");
  world.add(sun, DirectionalLight{.intensity = intensity});
  world.add(sun, Transform{}).rotation = look_rotation(sun_direction);
}

}  // namespace lg::test
