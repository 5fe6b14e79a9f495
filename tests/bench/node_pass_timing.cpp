#include "tests/bench/node_pass_timing.h"

#include <algorithm>
#include <vector>

namespace lg::bench {

Timing time_node(test::ExposureHarness& h, int frames, std::string_view prefix) {
  h.run_frame();
  std::vector<double> ms;
  for (int f = 0; f < frames; ++f) {
    const FrameStats stats = h.run_frame();
    double sum = 0;
    for (const PassStats& p : stats.passes)
      if (p.name.starts_with(prefix)) sum += p.gpu_ms;
    ms.push_back(sum);
  }
  std::sort(ms.begin(), ms.end());
  return {ms.front(), ms[ms.size() / 2]};
}

}  // namespace lg::bench
