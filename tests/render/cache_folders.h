// Folders and files for the tests of what the renderer keeps on disk (the pipeline cache, the
// static results): an empty folder of each test's own under the build folder, renderer options
// that keep the caches there, with validation on, and a file's bytes read and written.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
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

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace lg::test
