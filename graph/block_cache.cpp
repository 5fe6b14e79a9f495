#include "graph/block_cache.h"

#include <array>
#include <bit>
#include <mutex>
#include <new>
#include <utility>

namespace lg {
namespace {

constexpr size_t smallest_cached = 4096;
constexpr int class_count = 4 * 64;

// Sizes are rounded up to 2^b, 1.25 * 2^b, 1.5 * 2^b or 1.75 * 2^b: at most a quarter wasted,
// and a graph a little larger than the last still finds its blocks.
struct SizeClass {
  size_t bytes;
  int index;
};
SizeClass size_class(size_t bytes) {
  const int b = std::bit_width(bytes) - 1;
  const size_t step = size_t{1} << (b - 2);
  const size_t rounded = (bytes + step - 1) & ~(step - 1);
  const int rb = std::bit_width(rounded) - 1;
  return {rounded, 4 * rb + static_cast<int>((rounded >> (rb - 2)) & 3)};
}

// Free blocks, one list per class, linked through their first bytes. Never destroyed: plans in
// static storage may be freed after it would be.
class BlockCache {
 public:
  void* take(const SizeClass& c) {
    std::lock_guard lock(mutex_);
    FreeBlock* block = free_[c.index];
    if (!block) return nullptr;
    free_[c.index] = block->next;
    kept_ -= c.bytes;
    return block;
  }

  bool keep(void* p, const SizeClass& c) {
    std::lock_guard lock(mutex_);
    if (kept_ + c.bytes > block_cache_limit) return false;
    free_[c.index] = new (p) FreeBlock{free_[c.index]};
    kept_ += c.bytes;
    return true;
  }

  size_t release() {
    std::array<FreeBlock*, class_count> lists;
    size_t freed;
    {
      std::lock_guard lock(mutex_);
      lists = std::exchange(free_, {});
      freed = std::exchange(kept_, 0);
    }
    for (FreeBlock* block : lists)
      while (block) ::operator delete(std::exchange(block, block->next));
    return freed;
  }

  size_t kept() {
    std::lock_guard lock(mutex_);
    return kept_;
  }

 private:
  struct FreeBlock {
    FreeBlock* next;
  };
  std::mutex mutex_;
  std::array<FreeBlock*, class_count> free_{};
  size_t kept_ = 0;
};

BlockCache& cache() {
  static BlockCache& instance = *new BlockCache;
  return instance;
}

}  // namespace

void* cached_allocate(size_t bytes) {
  if (bytes < smallest_cached) return ::operator new(bytes);
  const SizeClass c = size_class(bytes);
  if (void* block = cache().take(c)) return block;
  return ::operator new(c.bytes);
}

void cached_free(void* block, size_t bytes) noexcept {
  if (bytes < smallest_cached) return ::operator delete(block);
  if (!cache().keep(block, size_class(bytes))) ::operator delete(block);
}

size_t release_cached_blocks() {
  return cache().release();
}
size_t cached_block_bytes() {
  return cache().kept();
}

}  // namespace lg
