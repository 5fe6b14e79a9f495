// Reading and writing the files the renderer keeps in its cache folder (the pipeline cache's,
// the static results'), the same way for both: a missing file is the first run, anything that is
// not a readable regular file is a problem to report, and writes are atomic into a folder made
// if missing. The callers decode, warn and keep their own messages.
#pragma once

#include <string>

namespace lg {

struct CacheFileRead {
  bool exists = false;   // false: no file there (nothing to report)
  std::string bytes;     // when it exists and was read
  std::string problem;   // why it exists but could not be read; empty when it was
};

CacheFileRead read_cache_file(const std::string& path);

// Writes `bytes` to `path` atomically, making `folder` first; empty, or why it failed.
std::string write_cache_file(const std::string& folder, const std::string& path, const std::string& bytes);

}  // namespace lg
