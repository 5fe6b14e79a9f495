// A node's GPU time in an ExposureHarness: the passes whose names begin with a prefix, summed
// per frame (shared by the benchmarks of post.bilateral and post.flare).
#pragma once

#include <string_view>

#include "tests/post/exposure_harness.h"

namespace lg::bench {

struct Timing {
  double fastest_ms = 0, median_ms = 0;
};

// One warm-up frame (it JIT-compiles the pipelines), then `frames` timed ones: the fastest and
// the median of the passes named `prefix`... summed in each ("flare/" for a node "flare").
Timing time_node(test::ExposureHarness& h, int frames, std::string_view prefix);

}  // namespace lg::bench
