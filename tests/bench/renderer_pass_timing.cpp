#include "tests/bench/renderer_pass_timing.h"

#include <sys/resource.h>

#include <algorithm>

#include "api/renderer.h"

namespace lg::bench {

double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) * 1e-3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

std::vector<double> sorted_pass_ms(Renderer& renderer, const World& world, uint32_t width, uint32_t height,
                                   uint32_t frames, const std::function<bool(const std::string&)>& counts) {
  std::vector<double> times;
  for (uint32_t f = 0; f <= frames; ++f) {
    const FrameStats& stats = renderer.render(world, {width, height});
    double ms = 0;
    for (const PassStats& p : stats.passes)
      if (counts(p.name)) ms += p.gpu_ms;
    if (f > 0) times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  return times;
}

}  // namespace lg::bench
