// Scene files (docs/scene-format.md): JSON that places meshes (glTF, OBJ or built-in shapes)
// with materials, lights of every kind, probes, the camera and the environment. Read with the
// project's JSON reader, so each error names file, line, column and JSON pointer; all the
// errors of a file are collected and thrown together as one SceneError (scene_error.h).
#pragma once

#include <string>
#include <string_view>

#include "graph/asset_paths.h"
#include "runtime/scene/mesh_occlusion.h"
#include "runtime/scene/world.h"

namespace lg {

inline constexpr const char* world_format = "lumagraph-world/1";

// Paths in the file resolve relative to it and must stay inside `roots` (default: its folder).
// An entity's "occlusion" bake is read with `read_occlusion`; without one it is an error.
World load_scene_file(const std::string& path, const AssetRoots& roots = {},
                      const OcclusionBakeReader& read_occlusion = {});
// The same for text already in memory; `path` names it in messages and anchors relative paths.
World parse_scene_file(std::string_view text, const std::string& path, const AssetRoots& roots = {},
                       const OcclusionBakeReader& read_occlusion = {});

}  // namespace lg
