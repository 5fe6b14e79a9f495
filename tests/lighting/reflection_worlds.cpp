#include "tests/lighting/reflection_worlds.h"

#include <stdexcept>

#include "api/world_loading.h"

namespace lg::test {
namespace {

World load_example_world(const std::string& name) {
  const std::string path = LUMAGRAPH_SOURCE_DIR "/examples/worlds/" + name + ".json";
  return load_world(path, renderer_world_options(path));
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

}  // namespace lg::test
