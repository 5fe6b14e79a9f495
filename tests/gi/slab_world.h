// Rooms of boxes for the one-bounce nodes' tests (gi.lpv, gi.voxel): one grey diffuse material
// added to `world`, and a function that adds a box of that material of `size` centred at `at`;
// and a closed room of such boxes.
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

// A closed room, 4 x 3 x 4 m inside with its floor at y = 0, of slabs `thickness` thick: nothing
// outside it can light its inside.
inline void add_closed_room(World& world, float albedo, float thickness) {
  const auto slab = slab_adder(world, albedo);
  const float t = thickness;
  slab({4 + 2 * t, t, 4 + 2 * t}, {0, -t / 2, 0});
  slab({4 + 2 * t, t, 4 + 2 * t}, {0, 3 + t / 2, 0});
  slab({t, 3, 4}, {-2 - t / 2, 1.5f, 0});
  slab({t, 3, 4}, {2 + t / 2, 1.5f, 0});
  slab({4, 3, t}, {0, 1.5f, -2 - t / 2});
  slab({4, 3, t}, {0, 1.5f, 2 + t / 2});
}

}  // namespace lg::test
