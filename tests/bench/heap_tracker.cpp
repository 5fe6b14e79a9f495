// Replacement global operator new / delete (every form: plain, array, nothrow, aligned, sized)
// that count bytes while a HeapScope is open. Sizes come from malloc_usable_size on both sides,
// so an unsized delete subtracts exactly what its new added.
#include "tests/bench/heap_tracker.h"

#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace lg::bench {
namespace {

std::atomic<bool> counting{false};
std::atomic<int64_t> current{0};
std::atomic<int64_t> peak{0};
std::atomic<uint64_t> allocations{0};

void note_alloc(void* p) {
  if (!counting.load(std::memory_order_relaxed)) return;
  auto size = static_cast<int64_t>(malloc_usable_size(p));
  int64_t now = current.fetch_add(size, std::memory_order_relaxed) + size;
  allocations.fetch_add(1, std::memory_order_relaxed);
  int64_t high = peak.load(std::memory_order_relaxed);
  while (now > high && !peak.compare_exchange_weak(high, now, std::memory_order_relaxed)) {
  }
}

void note_free(void* p) {
  if (p && counting.load(std::memory_order_relaxed))
    current.fetch_sub(static_cast<int64_t>(malloc_usable_size(p)), std::memory_order_relaxed);
}

void* allocate(std::size_t size, std::size_t alignment, bool nothrow) {
  if (size == 0) size = 1;
  void* p = nullptr;
  if (alignment <= alignof(std::max_align_t)) p = std::malloc(size);
  else if (posix_memalign(&p, alignment, size) != 0) p = nullptr;
  if (!p) {
    if (nothrow) return nullptr;
    throw std::bad_alloc();
  }
  note_alloc(p);
  return p;
}

void release(void* p) {
  note_free(p);
  std::free(p);
}

constexpr std::size_t plain = alignof(std::max_align_t);

}  // namespace

HeapScope::HeapScope() {
  current.store(0, std::memory_order_relaxed);
  peak.store(0, std::memory_order_relaxed);
  allocations.store(0, std::memory_order_relaxed);
  counting.store(true, std::memory_order_seq_cst);
}

HeapScope::~HeapScope() { counting.store(false, std::memory_order_seq_cst); }

HeapUsage HeapScope::usage() const {
  return {peak.load(std::memory_order_relaxed), current.load(std::memory_order_relaxed),
          allocations.load(std::memory_order_relaxed)};
}

}  // namespace lg::bench

using lg::bench::allocate;
using lg::bench::plain;
using lg::bench::release;

void* operator new(std::size_t n) { return allocate(n, plain, false); }
void* operator new[](std::size_t n) { return allocate(n, plain, false); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, plain, true); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate(n, plain, true); }
void* operator new(std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), false); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocate(n, static_cast<std::size_t>(a), false); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, static_cast<std::size_t>(a), true);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate(n, static_cast<std::size_t>(a), true);
}

void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
