// Path-traced references kept between runs of a benchmark (lumagraph-bench-reflections,
// lumagraph-bench-gi-methods): one part file (reference_file.h) a reference, named by the world,
// a tag of its options and the FNV-1a hash of the files it is traced from, and used only when
// the run line stored in it matches this run's, so an edited world or graph is traced again.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "nodes/gi/path_tracer/path_tracer.h"

namespace lg::bench {

struct CachedRun {
  std::string cache_dir;
  std::string world;               // the name the file and the messages start with
  std::vector<std::string> files;  // what the reference is traced from: their text keys it
  std::string options;             // the run's options as text, e.g. "size=320x180 spp=512 seed=1"
  std::string file_tag;            // the same in the file's name, e.g. "320x180-512-s1"
};

// The cached image when the cache holds this run, else `trace()`'s, saved there; prints which.
ReferenceImage cached_reference(const CachedRun& run, const std::function<ReferenceImage()>& trace);

}  // namespace lg::bench
