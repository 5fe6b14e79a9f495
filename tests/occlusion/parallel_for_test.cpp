// parallel_for: every index once, on any thread count, and a body's exception reaches the caller.
#include "nodes/raytrace/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace lg {
namespace {

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
  for (unsigned threads : {1u, 2u, 7u}) {
    for (size_t count : {size_t(0), size_t(1), size_t(5), size_t(10007)}) {
      std::vector<std::atomic<int>> runs(count);
      parallel_for(
          count, [&](size_t i) { runs[i]++; }, threads);
      for (size_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << "index " << i << " threads " << threads;
    }
  }
}

TEST(ParallelFor, RethrowsTheBodysException) {
  EXPECT_THROW(parallel_for(1000,
                            [](size_t i) {
                              if (i == 500) throw std::runtime_error("bad index");
                            }),
               std::runtime_error);
}

}  // namespace
}  // namespace lg
