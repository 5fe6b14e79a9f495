// Rooms of boxes for the one-bounce nodes' tests (gi.lpv, gi.voxel): one grey diffuse material
// added to `world`, and a function that adds a box of that material of `size` centred at `at`.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/scene/mesh_generators.h"
#include "runtime/scene/world.h"

namespace lg::test {

inline auto slab_adder(World& world, float albedo) {
  PbrMaterial grey;
  grey.base_color = glm::vec4(glm::vec3(albedo), 1.0f);
  const int material = world.add_material(grey);
  return [&world, material](glm::vec3 size, glm::vec3 at) {
    Entity e = world.create("slab");
    world.add(e, MeshRenderer{world.add_mesh(make_box(size)), material});
    world.add(e, Transform{}).position = at;
  };
}

}  // namespace lg::test
