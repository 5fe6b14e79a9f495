#include "tests/bench/renderer_pass_timing.h"

#include <sys/resource.h>

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

#include "api/renderer.h"
#include "runtime/scene/components.h"

namespace lg::bench {

double process_cpu_ms() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) * 1e-3; };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

namespace {

template <class Component>
void turn_each(World& world, double degrees) {
  const glm::quat turn = glm::angleAxis(float(glm::radians(degrees)), glm::vec3(0.0f, 1.0f, 0.0f));
  world.each<Component, Transform>([&](Entity, Component&, Transform& t) { t.rotation = turn * t.rotation; });
}

}  // namespace

void turn_cameras(World& world, double degrees) {
  turn_each<Camera>(world, degrees);
}

void turn_directional_lights(World& world, double degrees) {
  turn_each<DirectionalLight>(world, degrees);
}

std::vector<double> sorted_pass_ms(Renderer& renderer, const World& world, uint32_t width, uint32_t height,
                                   uint32_t frames, const std::function<bool(const std::string&)>& counts,
                                   double orbit_degrees) {
  World moving = world;
  std::vector<double> times;
  for (uint32_t f = 0; f <= frames; ++f) {
    if (orbit_degrees != 0.0) turn_cameras(moving, f % 2 == 0 ? orbit_degrees : -orbit_degrees);
    const FrameStats& stats = renderer.render(moving, {width, height});
    double ms = 0;
    for (const PassStats& p : stats.passes)
      if (counts(p.name)) ms += p.gpu_ms;
    if (f > 0) times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  return times;
}

}  // namespace lg::bench
