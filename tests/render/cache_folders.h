// Folders for the tests of what the renderer keeps on disk (the pipeline cache, the static
// results): an empty one of each test's own under the build folder, and renderer options that
// keep the caches there, with validation on.
#pragma once

#include <filesystem>
#include <string>

#include "api/renderer.h"

namespace lg::test {

// build/test-output/GROUP/NAME, emptied.
inline std::filesystem::path fresh_folder(const std::string& group, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(LUMAGRAPH_BINARY_DIR) / "test-output" / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline RendererOptions options_with_cache(const std::filesystem::path& folder) {
  RendererOptions options;
  options.device.validation = true;
  options.pipeline_cache_folder = folder.string();
  return options;
}

}  // namespace lg::test
