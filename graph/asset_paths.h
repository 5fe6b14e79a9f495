// File paths inside graph files are untrusted: they resolve relative to the graph file and must
// stay inside the allowed asset roots (by default the graph file's folder), after following
// "..", symbolic links and absolute paths.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lg {

struct AssetRoots {
  std::vector<std::string> roots;  // empty: the graph file's folder (or the working folder)
};

// The absolute, canonical path of `value`, or nullopt with `error` saying what is wrong.
std::optional<std::string> resolve_asset_path(const std::string& graph_file, const std::string& value,
                                              const AssetRoots& allowed, const std::vector<std::string>& extensions,
                                              std::string* error);

}  // namespace lg
