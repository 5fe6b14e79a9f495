// Keeps a context's pipeline cache (Context::pipelines()) on disk between runs, in
// FOLDER/pipeline-cache-<device hash>.bin (pipeline_cache_file.h): loaded when the store is made,
// written atomically by save(). A missing file is the first run; an unreadable, truncated,
// corrupt or foreign one is ignored with one warning naming the file and what was wrong, and a
// folder that cannot be written costs one warning: neither ever fails a render.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lg {

class Context;

// $XDG_CACHE_HOME/lumagraph, else $HOME/.cache/lumagraph; empty when neither is set.
std::string default_pipeline_cache_folder();
// LUMAGRAPH_PIPELINE_CACHE=off (or 0, false, no) in the environment turns the disk cache off.
bool pipeline_cache_disabled_by_environment();

class PipelineCacheStore {
 public:
  PipelineCacheStore(Context& context, const std::string& folder);

  const std::string& path() const { return path_; }
  // Bytes of driver data read from the file and handed to the driver; 0 when none was.
  size_t loaded_bytes() const { return loaded_bytes_; }
  // Writes the driver's cache when the driver made pipelines since the last save (or the load)
  // and its data differs from the file's (lavapipe's never holds more than its header).
  // False when writing failed: the first failure adds a warning, later saves do not try again.
  bool save();
  // Warnings since the last call, one line each.
  std::vector<std::string> take_warnings();

 private:
  void load();
  uint64_t compiled() const;  // pipelines the driver made without its cache, so far

  Context& context_;
  std::string folder_, path_;
  size_t loaded_bytes_ = 0;
  uint64_t compiled_at_save_ = 0;
  std::optional<uint64_t> file_data_hash_;  // of the driver data the file holds, once read or written
  bool unwritable_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace lg
