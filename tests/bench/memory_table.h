// Transient memory of the example graphs with and without aliasing: every examples/*.json is
// compiled with the built-in node registry and the default scene at each frame size, once with
// aliasing on and once with it off.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "graph/compiler/lower.h"

namespace lg::bench {

struct MemoryRow {
  std::string example;  // file name, "default.json"
  FrameSize frame;
  std::string error;             // non-empty when the example did not compile
  uint64_t unaliased = 0;        // block 0 with options.alias.enabled = false
  uint64_t aliased = 0;          // block 0 with aliasing (Plan::memory.transient)
  uint64_t unaliased_sum = 0;    // Plan::memory.transient_unaliased: sizes summed, no alignment
  uint64_t persistent = 0;       // cached and history resources (block 1)
  uint64_t live_peak = 0;        // most bytes of block 0 alive at one pass: no aliasing gets below it
  int transient_resources = 0;   // resources placed in block 0

  double saving_percent() const;  // aliased vs unaliased
};

// Compiles every *.json directly inside `examples_dir`, sorted by name, at each frame size.
std::vector<MemoryRow> measure_memory(const std::string& examples_dir, const std::vector<FrameSize>& frames);

void print_memory_table(std::FILE* out, const std::vector<MemoryRow>& rows);
bool write_memory_csv(const std::string& path, const std::vector<MemoryRow>& rows, std::string* error);

}  // namespace lg::bench
