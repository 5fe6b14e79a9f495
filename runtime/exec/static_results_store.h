// Keeps plans' static results (static_results_file.h) on disk between runs, beside the pipeline
// cache: FOLDER/static-results-<key>.bin, written after a frame that ran the static passes and
// loaded into the next run's executor instead of running them. The key covers everything that
// changes the bytes (static_results_key: passes' cache keys, resources' shapes, the device and
// driver, the shaders and build, the contents of files static nodes read: hashed once a process
// while a file keeps its size and modification time), so a stale file is never found, only left
// to age out. A missing file is a miss; an unreadable, truncated, corrupt
// or foreign one is ignored with one warning naming the file and why, and written afresh once
// the passes have run. Writes are atomic (a temporary file, then rename). The folder is bounded:
// after each write, the least recently used results files (by modification time, which a load
// refreshes) are removed until the rest take at most max_bytes. Nothing here fails a render.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "runtime/exec/static_results_file.h"

namespace lg {

class Executor;

class StaticResultsStore {
 public:
  static constexpr uint64_t default_max_bytes = uint64_t{256} << 20;

  // `identity.inputs` is ignored: key_for() hashes each plan's input files.
  StaticResultsStore(std::string folder, const StaticResultsIdentity& identity, uint64_t max_bytes = default_max_bytes);

  // The key of `plan`'s static results, given the files its static nodes read; 0 when there is
  // nothing to keep (no static pass) or an input file cannot be read (its node reports that).
  uint64_t key_for(const Plan& plan, std::span<const std::string> input_files) const;
  std::string path(uint64_t key) const;

  // Loads the results for `key` into `executor` (before its first frame): true when its next
  // frame skips the static passes.
  bool load(Executor& executor, uint64_t key);
  // Writes the executor's results (after a frame that ran its static passes) under `key`, then
  // bounds the folder. False when nothing was written.
  bool save(Executor& executor, uint64_t key);

  // Warnings since the last call, one line each.
  std::vector<std::string> take_warnings();

 private:
  void bound_folder(const std::string& keep);

  std::string folder_;
  StaticResultsIdentity identity_;
  uint64_t max_bytes_;
  bool unwritable_ = false;
  std::vector<std::string> warnings_;
};

}  // namespace lg
