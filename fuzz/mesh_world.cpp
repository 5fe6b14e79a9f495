#include "fuzz/mesh_world.h"

#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"

namespace lg::fuzz {

void load_mesh_world(const std::string& path) {
  try {
    World world = load_world(path);
    (void)make_scene_view(world, 16.0f / 9.0f).summary();
  } catch (const SceneError&) {
  }
}

}  // namespace lg::fuzz
