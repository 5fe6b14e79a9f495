// The benchmarks' reference cache (tests/bench/reference_cache.h): a reference is traced once
// and read back unchanged, and traced again when a file it comes from or its options change, so
// an edited world never reuses a stale reference.
#include "tests/bench/reference_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace lg::bench {
namespace {

namespace fs = std::filesystem;

// A 2x1 image whose values say which trace made it.
ReferenceImage traced_image(int trace) {
  ReferenceImage im;
  im.width = 2, im.height = 1, im.row_begin = 0, im.row_end = 1;
  for (size_t a = 0; a < kReferenceAovCount; ++a)
    for (int i = 0; i < 2; ++i) {
      im.mean[a].push_back(glm::vec3(float(trace), float(a), float(i) + 0.25f));
      im.standard_error[a].push_back(glm::vec3(0.5f));
    }
  return im;
}

TEST(ReferenceCache, TracesOnceAndAgainWhenItsWorldOrOptionsChange) {
  const fs::path dir = fs::path(LUMAGRAPH_BINARY_DIR) / "reference-cache-test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string world = (dir / "world.json").string();
  std::ofstream(world) << "{ \"a\": 1 }";
  int traces = 0;
  const auto trace = [&] { return traced_image(++traces); };
  CachedRun run{(dir / "cache").string(), "box", {world}, "size=2x1 spp=4", "2x1-4"};

  const ReferenceImage first = cached_reference(run, trace);
  const ReferenceImage again = cached_reference(run, trace);
  EXPECT_EQ(traces, 1);
  EXPECT_EQ(again.mean_of(ReferenceAov::indirect_diffuse), first.mean_of(ReferenceAov::indirect_diffuse));
  EXPECT_EQ(again.error_of(ReferenceAov::radiance), first.error_of(ReferenceAov::radiance));

  std::ofstream(world) << "{ \"a\": 2 }";  // the world edited
  EXPECT_EQ(cached_reference(run, trace).mean_of(ReferenceAov::radiance)[0].x, 2.0f);
  run.options = "size=2x1 spp=8";  // same file name, another run line
  EXPECT_EQ(cached_reference(run, trace).mean_of(ReferenceAov::radiance)[0].x, 3.0f);
  EXPECT_EQ(traces, 3);
  run.world = "missing", run.files = {(dir / "none.json").string()};
  EXPECT_THROW(cached_reference(run, trace), std::runtime_error);
}

}  // namespace
}  // namespace lg::bench
