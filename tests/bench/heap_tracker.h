// Heap accounting for the benchmarks and the env.load memory test: heap_tracker.cpp replaces
// the global operator new and delete of the binary it is linked into. While a HeapScope is
// open, every allocation and free adds to or subtracts from a running total (the malloc'd
// block's usable size) and the highest total is kept. Outside a scope the operators only
// forward to malloc and free, so timed loops are not slowed down. Single-threaded use: one
// scope at a time.
#pragma once

#include <cstdint>

namespace lg::bench {

struct HeapUsage {
  int64_t peak_bytes = 0;    // highest net growth over the scope's start
  int64_t net_bytes = 0;     // growth still held when the scope closed
  uint64_t allocations = 0;  // calls to operator new inside the scope
};

class HeapScope {
 public:
  HeapScope();  // starts counting from zero
  ~HeapScope();
  HeapScope(const HeapScope&) = delete;
  HeapScope& operator=(const HeapScope&) = delete;

  HeapUsage usage() const;  // so far
};

}  // namespace lg::bench
