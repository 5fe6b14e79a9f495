#include "api/world_loading.h"

#include <filesystem>

#include "nodes/occlusion/baked/occlusion_bake_reader.h"

namespace lg {

WorldLoadOptions renderer_world_options(const std::string& path, const std::vector<std::string>& asset_roots) {
  WorldLoadOptions options;
  options.read_occlusion = read_occlusion_bake;
  options.asset_roots.roots = asset_roots;
  // Empty roots already mean the file's folder; given roots replace that default, so it is added.
  if (!asset_roots.empty()) options.asset_roots.roots.push_back(std::filesystem::absolute(path).parent_path().string());
  return options;
}

}  // namespace lg
