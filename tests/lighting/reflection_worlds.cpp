#include "tests/lighting/reflection_worlds.h"

#include <stdexcept>

#include "api/world_loading.h"

namespace lg::test {
namespace {

World load_example_world(const std::string& name) {
  const std::string path = LUMAGRAPH_SOURCE_DIR "/examples/worlds/" + name + ".json";
  return load_world(path, renderer_world_options(path));
}

// Gives the entity `name` of `file`'s world a metal material of its own (its material may be
// shared with other entities).
void make_metal(World& world, const std::string& name, float roughness, const char* file) {
  bool found = false;
  world.each<Name, MeshRenderer>([&](Entity, const Name& n, MeshRenderer& r) {
    if (n.value != name) return;
    PbrMaterial metal;
    metal.name = name + " metal";
    metal.base_color = {0.9f, 0.9f, 0.9f, 1.0f};
    metal.roughness = roughness;
    metal.metalness = 1.0f;
    r.material = world.add_material(metal);
    found = true;
  });
  if (!found) throw std::runtime_error(std::string(file) + " has no mesh entity '" + name + "'");
}

}  // namespace

ReflectionWorld reflection_room() {
  return {"reflection-room", load_example_world("reflection-room"), 0.1f, 0.05f};
}

ReflectionWorld polished_gallery() {
  constexpr float kFloorRoughness = 0.2f;
  World world = load_example_world("gallery");
  bool found = false;
  for (size_t i = 0; i < world.materials().size(); ++i)
    if (world.materials()[i].name == "floor") {
      PbrMaterial& floor = world.edit_material(int(i));
      floor.base_color = {0.9f, 0.9f, 0.9f, 1.0f};
      floor.roughness = kFloorRoughness;
      floor.metalness = 1.0f;
      found = true;
    }
  if (!found) throw std::runtime_error("examples/worlds/gallery.json has no material 'floor'");
  return {"gallery-polished", std::move(world), kFloorRoughness, 0.05f};
}

ReflectionWorld polished_cornell_box() {
  constexpr float kFloorRoughness = 0.2f, kBlockRoughness = 0.05f;
  World world = load_example_world("cornell-box");
  make_metal(world, "floor", kFloorRoughness, "examples/worlds/cornell-box.json");
  make_metal(world, "tall block", kBlockRoughness, "examples/worlds/cornell-box.json");
  return {"cornell-polished", std::move(world), kFloorRoughness, kBlockRoughness};
}

}  // namespace lg::test
