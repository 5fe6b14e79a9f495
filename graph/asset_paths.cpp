#include "graph/asset_paths.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace lg {
namespace fs = std::filesystem;
namespace {

bool is_inside(const fs::path& path, const fs::path& root) {
  auto [root_end, path_it] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return root_end == root.end();
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::optional<std::string> resolve_asset_path(const std::string& graph_file, const std::string& value,
                                              const AssetRoots& allowed, const std::vector<std::string>& extensions,
                                              std::string* error) {
  auto fail = [&](std::string message) -> std::optional<std::string> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (value.empty()) return fail("the path is empty");
  if (value.find('\0') != std::string::npos) return fail("the path contains a NUL character");
  std::error_code ec;
  fs::path base = graph_file.empty() ? fs::current_path(ec) : fs::absolute(fs::path(graph_file), ec).parent_path();
  fs::path resolved = fs::weakly_canonical(base / fs::path(value), ec);
  if (ec) return fail("cannot resolve the path: " + ec.message());

  std::vector<fs::path> roots;
  if (allowed.roots.empty()) roots.push_back(fs::weakly_canonical(base, ec));
  for (const auto& r : allowed.roots) roots.push_back(fs::weakly_canonical(fs::absolute(r, ec), ec));
  bool inside = false;
  for (const auto& r : roots) inside |= is_inside(resolved, r);
  if (!inside) {
    std::string list;
    for (const auto& r : roots) list += (list.empty() ? "" : ", ") + r.string();
    return fail("'" + value + "' resolves to " + resolved.string() + ", outside the allowed asset roots (" + list +
                "); pass --asset-root to allow another folder");
  }
  if (!extensions.empty()) {
    std::string ext = lower(resolved.extension().string());
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
      std::string list;
      for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
      return fail("'" + value + "' has the extension '" + ext + "'; expected one of " + list);
    }
  }
  if (!fs::is_regular_file(resolved, ec)) return fail("'" + value + "' does not exist (looked for " + resolved.string() + ")");
  return resolved.string();
}

}  // namespace lg
