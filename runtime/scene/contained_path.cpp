#include "runtime/scene/contained_path.h"

#include <algorithm>
#include <filesystem>

namespace lg {

std::string folder_of(const std::string& file) {
  std::error_code ec;
  return std::filesystem::weakly_canonical(std::filesystem::absolute(file, ec), ec).parent_path().string();
}

bool inside_folder(const std::string& path, const std::string& folder) {
  std::error_code ec;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(path, ec);
  if (ec) return false;
  std::filesystem::path root(folder);
  auto [root_end, unused] = std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  return root_end == root.end();
}

}  // namespace lg
