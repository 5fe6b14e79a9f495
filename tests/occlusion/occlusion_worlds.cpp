#include "tests/occlusion/occlusion_worlds.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <string>

namespace lg::test {

WorldBuilder::WorldBuilder() {
  material_ = world_.add_material({.name = "grey", .base_color = glm::vec4(0.8f), .roughness = 0.8f});
}

WorldBuilder& WorldBuilder::add(MeshData mesh, glm::vec3 position, float yaw_degrees) {
  Entity e = world_.create("shape " + std::to_string(world_.meshes().size()));
  world_.add(e, MeshRenderer{world_.add_mesh(std::move(mesh)), material_});
  Transform& t = world_.add(e, Transform{});
  t.position = position;
  t.rotation = glm::angleAxis(glm::radians(yaw_degrees), glm::vec3(0.0f, 1.0f, 0.0f));
  return *this;
}

WorldBuilder& WorldBuilder::camera(glm::vec3 eye, glm::vec3 target, float vertical_fov_degrees, float near_plane) {
  Entity e = world_.create("camera");
  world_.add(e, Camera{.vertical_fov = glm::radians(vertical_fov_degrees), .near_plane = near_plane});
  Transform& t = world_.add(e, Transform{});
  t.position = eye;
  t.rotation = look_rotation(glm::normalize(target - eye));
  return *this;
}

}  // namespace lg::test
