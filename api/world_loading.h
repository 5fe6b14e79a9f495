// How a host of the renderer loads a world: load_world() with the nodes' reader for the bakes a
// scene file's "occlusion" keys name, so that occlusion.baked finds them, and with the paths
// the file may use: its own folder and the asset roots given.
#pragma once

#include <string>
#include <vector>

#include "runtime/scene/load_world.h"

namespace lg {

WorldLoadOptions renderer_world_options(const std::string& path, const std::vector<std::string>& asset_roots = {});

}  // namespace lg
