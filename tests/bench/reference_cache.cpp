#include "tests/bench/reference_cache.h"

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "graph/fnv1a.h"
#include "nodes/gi/path_tracer/reference_file.h"

namespace lg::bench {
namespace {

std::string file_text(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("reference cache: cannot read " + path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

ReferenceImage cached_reference(const CachedRun& run, const std::function<ReferenceImage()>& trace) {
  std::string sources;
  for (const std::string& file : run.files) sources += file_text(file);
  const uint64_t hash = fnv1a(sources);
  char hash_text[17];
  std::snprintf(hash_text, sizeof hash_text, "%016" PRIx64, hash);
  const std::string line = "world=" + run.world + " files=" + hash_text + " " + run.options;
  const std::string path = run.cache_dir + "/" + run.world + "-" + run.file_tag + "-" + hash_text + ".part";
  if (std::filesystem::exists(path)) {
    ReferencePart part = read_reference_part(path);
    if (part.run == line) {
      std::printf("%s reference: cached in %s\n", run.world.c_str(), path.c_str());
      return std::move(part.image);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  ReferencePart part{line, 0, 1, trace()};
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  std::filesystem::create_directories(run.cache_dir);
  write_reference_part(path, part);
  std::printf("%s reference: traced in %.0f s, saved to %s\n", run.world.c_str(), seconds.count(), path.c_str());
  return std::move(part.image);
}

}  // namespace lg::bench
