// libFuzzer harness: a scene file (world JSON) through the scene loader, from memory, anchored
// in the harness's empty folder (so meshes and bakes it names are missing files, reported as
// errors), then what `render` does with a loaded world: viewing defaults, the SceneView and its
// summary for the compiler. A bad file must be a SceneError, never a crash.
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "nodes/occlusion/baked/occlusion_bake_reader.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/scene_error.h"
#include "runtime/scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = (std::filesystem::path(lg::fuzz::input_folder()) / "world.json").string();
  try {
    lg::World world = lg::parse_scene_file(lg::fuzz::as_text(data, size), path, {}, lg::read_occlusion_bake);
    lg::add_viewing_defaults(world);
    (void)lg::make_scene_view(world, 16.0f / 9.0f).summary();
  } catch (const lg::SceneError&) {
  }
  return 0;
}
