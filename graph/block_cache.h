// Memory for the compiler's arrays and the Plan's, kept between compiles. glibc hands the free
// top of its heap back to the kernel once it passes a threshold, so a compile after a freed one
// faults every page of its arrays in again: at 10,000 nodes about 1,600 faults, 4 ms of a
// 14 ms compile on a 2-core VM. Blocks of 4 KiB or more are kept when freed, by size class
// (quarter steps between powers of two), and handed out again; smaller ones go to the heap.
// What the cache holds is bounded (block_cache_limit) and can be handed back at any time.
#pragma once

#include <cstddef>
#include <vector>

namespace lg {

inline constexpr size_t block_cache_limit = 64u << 20;  // bytes of free blocks kept at most

void* cached_allocate(size_t bytes);
void cached_free(void* block, size_t bytes) noexcept;

// Frees every block the cache keeps (a host that compiled its graphs at load time and wants
// the memory back). Returns the bytes freed.
size_t release_cached_blocks();
size_t cached_block_bytes();  // what the cache keeps now, free for the next compile

// A stateless allocator over the cache, for std::vector.
template <class T>
struct CachedAllocator {
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "the cache hands out operator new's alignment");
  using value_type = T;
  CachedAllocator() = default;
  template <class U>
  CachedAllocator(const CachedAllocator<U>&) noexcept {}
  T* allocate(size_t n) { return static_cast<T*>(cached_allocate(n * sizeof(T))); }
  void deallocate(T* p, size_t n) noexcept { cached_free(p, n * sizeof(T)); }
  friend bool operator==(CachedAllocator, CachedAllocator) { return true; }
};

template <class T>
using CachedVector = std::vector<T, CachedAllocator<T>>;

}  // namespace lg
