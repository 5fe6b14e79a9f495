// The compiler's block cache: freed blocks of 4 KiB or more come back for requests of their
// size class, smaller ones are not kept, what it keeps stays under its limit, and release
// hands everything back.
#include "graph/block_cache.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <vector>

#include "graph/compiler.h"
#include "tests/support/synthetic_graphs.h"

namespace lg {
namespace {

class BlockCacheTest : public ::testing::Test {
 protected:
  void SetUp() override { release_cached_blocks(); }
  void TearDown() override { release_cached_blocks(); }
};

TEST_F(BlockCacheTest, AFreedBlockServesTheNextRequestOfItsClass) {
  void* first = cached_allocate(100'000);
  cached_free(first, 100'000);
  // 100,000 bytes round up to 1.75 * 65,536 = 114,688, a class 110,000 bytes share.
  EXPECT_EQ(cached_block_bytes(), 114'688u);
  void* second = cached_allocate(110'000);
  EXPECT_EQ(second, first);
  EXPECT_EQ(cached_block_bytes(), 0u);
  cached_free(second, 110'000);
}

TEST_F(BlockCacheTest, AnotherClassGetsAFreshBlock) {
  void* block = cached_allocate(100'000);
  cached_free(block, 100'000);
  void* larger = cached_allocate(120'000);  // the next class up, 2 * 65,536
  EXPECT_EQ(cached_block_bytes(), 114'688u);
  cached_free(larger, 120'000);
  EXPECT_EQ(cached_block_bytes(), 114'688u + 131'072u);
}

TEST_F(BlockCacheTest, SmallBlocksAreNotKept) {
  cached_free(cached_allocate(4095), 4095);
  EXPECT_EQ(cached_block_bytes(), 0u);
  cached_free(cached_allocate(4096), 4096);
  EXPECT_EQ(cached_block_bytes(), 4096u);
}

TEST_F(BlockCacheTest, KeepsNoMoreThanItsLimit) {
  constexpr size_t bytes = 8u << 20;  // a size class of its own
  std::vector<void*> blocks;
  for (size_t k = 0; k < block_cache_limit / bytes + 3; ++k) blocks.push_back(cached_allocate(bytes));
  for (void* b : blocks) cached_free(b, bytes);
  EXPECT_EQ(cached_block_bytes(), block_cache_limit);
  EXPECT_EQ(release_cached_blocks(), block_cache_limit);
  EXPECT_EQ(cached_block_bytes(), 0u);
}

TEST_F(BlockCacheTest, ACompileLeavesItsArraysForTheNext) {
  const Graph graph = test::make_random_dag({.nodes = 2000, .dead_fraction = 0.3, .seed = 7});
  Diagnostics diagnostics;
  { compile(graph, test::synthetic_registry(), {}, diagnostics); }
  const size_t kept = cached_block_bytes();
  EXPECT_GT(kept, 0u);
  // The same graph again takes its blocks from the cache and gives them back.
  { compile(graph, test::synthetic_registry(), {}, diagnostics); }
  EXPECT_EQ(cached_block_bytes(), kept);
  EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.to_string();
}

// The editor compiles on a worker thread while the UI thread frees the plan it replaced, so
// two threads take and give back blocks at once. Each marks the blocks it holds; a block handed
// to both (a list corrupted by a race) shows the other's mark.
TEST_F(BlockCacheTest, ThreadsNeverShareABlock) {
  constexpr size_t sizes[] = {4096, 6000, 9000};
  int clashes[2] = {0, 0};
  auto churn = [&](uint64_t mark, int* clash) {
    for (int round = 0; round < 100'000; ++round) {
      uint64_t* held[3];
      for (int k = 0; k < 3; ++k) {
        held[k] = static_cast<uint64_t*>(cached_allocate(sizes[k]));
        held[k][0] = held[k][1] = mark;
      }
      for (int k = 0; k < 3; ++k) {
        *clash += held[k][0] != mark || held[k][1] != mark;
        cached_free(held[k], sizes[k]);
      }
    }
  };
  std::thread a(churn, 1, &clashes[0]), b(churn, 2, &clashes[1]);
  a.join();
  b.join();
  EXPECT_EQ(clashes[0] + clashes[1], 0);
}

}  // namespace
}  // namespace lg
