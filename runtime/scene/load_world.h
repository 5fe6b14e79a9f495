// The entry point for loading a world from a file, by extension: a scene file (.json,
// scene_file.h), or a lone glTF (.gltf, .glb) or OBJ (.obj) mesh, which gets what it lacks to be
// seen: a camera framing its bounds, a sun and the procedural sky. Every failure throws one
// SceneError (scene_error.h) holding all the located errors.
#pragma once

#include <string>

#include "graph/asset_paths.h"
#include "runtime/scene/mesh_occlusion.h"
#include "runtime/scene/world.h"

namespace lg {

struct WorldLoadOptions {
  AssetRoots asset_roots;  // where a scene file's paths may point; empty: the scene file's folder
  // Reads the .lgbake files a scene file's "occlusion" keys name; unset, such a key is an error.
  // The nodes provide one: lg::read_occlusion_bake (nodes/occlusion/baked/occlusion_bake_reader.h),
  // which lg::renderer_world_options (api/world_loading.h) sets.
  OcclusionBakeReader read_occlusion;
};

World load_world(const std::string& path, const WorldLoadOptions& options = {});

// Adds to `world` whatever of a camera (framing every draw from the front and above), a
// directional light (when it has no light at all) and an environment (the sky) it lacks.
void add_viewing_defaults(World& world);

}  // namespace lg
