// Small worlds built in code for the occlusion tests: shapes placed on demand and a camera
// looking from a point toward another, so each test states its geometry in a few lines.
#pragma once

#include <glm/vec3.hpp>

#include "runtime/scene/scene_view.h"
#include "runtime/scene/world.h"

namespace lg::test {

class WorldBuilder {
 public:
  WorldBuilder();
  // A mesh (from runtime/scene/mesh_generators.h) at `position`, turned by `yaw_degrees` about +Y.
  WorldBuilder& add(MeshData mesh, glm::vec3 position, float yaw_degrees = 0.0f);
  WorldBuilder& camera(glm::vec3 eye, glm::vec3 target, float vertical_fov_degrees = 50.0f, float near_plane = 0.05f);
  const World& world() const { return world_; }

 private:
  World world_;
  int material_ = -1;
};

}  // namespace lg::test
