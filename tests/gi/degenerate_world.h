// The world the one-bounce nodes (gi.lpv, gi.voxel) must stay finite on: zero-area triangles (all
// three corners on one point, and on one line) with normals of zero length, a NaN base colour on
// one mesh, a floor, and a sun 1e30 W/m^2 bright, seen by one camera.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <utility>

#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"

namespace lg::test {

inline World degenerate_world() {
  World world;
  PbrMaterial plain;
  PbrMaterial broken;
  broken.base_color = glm::vec4(std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f, 1.0f);
  Entity floor = world.create("floor");
  world.add(floor, MeshRenderer{world.add_mesh(make_quad(4.0f, 4.0f)), world.add_material(plain)});
  world.add(floor, Transform{});
  Entity box = world.create("box");
  world.add(box, MeshRenderer{world.add_mesh(make_box({1.0f, 1.0f, 1.0f})), world.add_material(broken)});
  world.add(box, Transform{}).position = {0.5f, 0.5f, 0.0f};
  MeshData flat;
  flat.positions = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {-1, 0.5f, 0}, {0, 0.5f, 0}, {1, 0.5f, 0}};
  flat.normals.assign(6, glm::vec3(0.0f));
  flat.indices = {0, 1, 2, 3, 4, 5};
  Entity degenerate = world.create("degenerate");
  world.add(degenerate, MeshRenderer{world.add_mesh(std::move(flat)), world.add_material(plain)});
  world.add(degenerate, Transform{});
  Entity camera = world.create("camera");
  world.add(camera, Camera{});
  Transform& eye = world.add(camera, Transform{});
  eye.position = {0.0f, 2.0f, 4.0f};
  eye.rotation = look_rotation({0.0f, -0.4f, -1.0f});
  Entity sun = world.create("sun");
  world.add(sun, DirectionalLight{.intensity = 1e30f});
  world.add(sun, Transform{}).rotation = look_rotation({0.3f, -1.0f, -0.4f});
  return world;
}

}  // namespace lg::test
