#include "runtime/exec/static_results_store.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <utility>

#include "graph/fnv1a.h"
#include "runtime/exec/executor.h"
#include "runtime/gpu/cache_file_io.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view file_prefix = "static-results-", file_suffix = ".bin";

bool is_results_file(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  std::error_code error;
  return name.starts_with(file_prefix) && name.ends_with(file_suffix) && entry.is_regular_file(error);
}

// The hash of a file's contents, read in blocks, chained onto `hash`; false when it cannot be read.
bool hash_contents(const std::string& path, uint64_t& hash) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::vector<char> block(1 << 20);
  while (in) {
    in.read(block.data(), std::streamsize(block.size()));
    hash = fnv1a(block.data(), size_t(in.gcount()), hash);
  }
  return !in.bad();
}

// What hash_contents() gave, kept for the process: the editor compiles its plan again on every
// param edit, and a large environment was read and hashed each time. An entry is used while the
// file keeps its size and modification time (a rewrite within the clock's resolution that keeps
// the size is not seen); a lock, as the editor compiles on one thread and renders on another.
class FileHashMemo {
 public:
  bool hash(const std::string& path, uint64_t& hash) {
    std::error_code error;
    const fs::path canonical = fs::canonical(path, error);
    const uintmax_t size = error ? 0 : fs::file_size(canonical, error);
    const fs::file_time_type modified = error ? fs::file_time_type() : fs::last_write_time(canonical, error);
    if (error) return hash_contents(path, hash);  // not a file: reading it says so
    const std::string where = canonical.string();
    const Stamped now{hash, size, modified, 0};  // stamped before the read: a write during it is seen next time
    {
      std::lock_guard lock(mutex_);
      const auto known = hashes_.find(where);
      if (known != hashes_.end() && known->second.same_as(now)) {
        hash = known->second.hash;
        return true;
      }
    }
    if (!hash_contents(path, hash)) return false;
    std::lock_guard lock(mutex_);
    hashes_[where] = {now.chained_onto, size, modified, hash};
    return true;
  }

 private:
  struct Stamped {
    uint64_t chained_onto;  // the hash the contents continue (the files before it in the key)
    uintmax_t size;
    fs::file_time_type modified;
    uint64_t hash;
    bool same_as(const Stamped& o) const {
      return chained_onto == o.chained_onto && size == o.size && modified == o.modified;
    }
  };
  std::mutex mutex_;
  std::map<std::string, Stamped> hashes_;  // one entry a file: bounded by the files a process reads
};

bool hash_file(const std::string& path, uint64_t& hash) {
  static FileHashMemo memo;
  return memo.hash(path, hash);
}

}  // namespace

StaticResultsStore::StaticResultsStore(std::string folder, const StaticResultsIdentity& identity, uint64_t max_bytes)
    : folder_(std::move(folder)), identity_(identity), max_bytes_(max_bytes) {}

uint64_t StaticResultsStore::key_for(const Plan& plan, std::span<const std::string> input_files) const {
  StaticResultsIdentity identity = identity_;
  identity.inputs = fnv1a_basis;
  for (const std::string& file : input_files) {
    identity.inputs = fnv1a(file, identity.inputs);
    if (!hash_file(file, identity.inputs)) return 0;
  }
  return static_results_key(plan, identity);
}

std::string StaticResultsStore::path(uint64_t key) const {
  return folder_ + "/" + static_results_file_name(key);
}

bool StaticResultsStore::load(Executor& executor, uint64_t key) {
  if (key == 0) return false;
  const std::string file = path(key);
  const CacheFileRead read = read_cache_file(file);
  if (!read.exists) return false;  // the first run of this plan
  auto ignored = [&](const std::string& why) {
    warnings_.push_back("static results " + file + " ignored (the static passes run again): " + why);
    return false;
  };
  if (!read.problem.empty()) return ignored(read.problem);
  DecodedStaticResults decoded = decode_static_results(read.bytes, identity_.device, key);
  if (!decoded.problem.empty()) return ignored(decoded.problem);
  if (std::string problem = executor.load_cached_results(decoded.results); !problem.empty()) return ignored(problem);
  std::error_code error;
  fs::last_write_time(file, fs::file_time_type::clock::now(), error);  // used: the last to go
  return true;
}

bool StaticResultsStore::save(Executor& executor, uint64_t key) {
  if (key == 0 || unwritable_) return false;
  const std::string file = path(key);
  std::string error;
  try {
    const std::vector<StoredResult> results = executor.read_cached_results();
    if (results.empty()) return false;
    const std::string bytes = encode_static_results(identity_.device, key, results);
    if (bytes.size() > max_bytes_) {
      warnings_.push_back("static results " + file + " not saved: " + std::to_string(bytes.size() >> 20) +
                          " MiB, more than the folder may hold (" + std::to_string(max_bytes_ >> 20) + " MiB)");
      return false;
    }
    error = write_cache_file(folder_, file, bytes);
  } catch (const std::exception& e) {  // a readback failed: the device is lost
    error = e.what();
  }
  if (!error.empty()) {
    unwritable_ = true;
    warnings_.push_back("static results " + file + " not saved (the static passes run again next run): " + error);
    return false;
  }
  bound_folder(file);
  return true;
}

void StaticResultsStore::bound_folder(const std::string& keep) {
  struct Entry {
    fs::file_time_type used;
    uint64_t bytes;
    fs::path path;
  };
  std::vector<Entry> entries;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder_, error)) {
    if (!is_results_file(entry)) continue;
    std::error_code e1, e2;
    Entry e{entry.last_write_time(e1), entry.file_size(e2), entry.path()};
    if (!e1 && !e2) entries.push_back(std::move(e));
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used > b.used; });
  uint64_t total = 0;  // of the files kept, the most recently used first
  for (const Entry& e : entries) {
    if (total + e.bytes > max_bytes_ && e.path != fs::path(keep))
      fs::remove(e.path, error);
    else
      total += e.bytes;
  }
}

std::vector<std::string> StaticResultsStore::take_warnings() {
  return std::exchange(warnings_, {});
}

}  // namespace lg
