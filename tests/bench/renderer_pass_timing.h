// Some passes' GPU time in a Renderer, per frame (the benchmarks of gi.prt and
// lighting.deferred's area pass), and the process's CPU time (gi.lpv's). Light types stay out of
// this header: area_specular_bench.cpp includes it beside the renderer's own names for them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lg {
class Renderer;
class World;
}  // namespace lg

namespace lg::bench {

// The CPU time this process has used, all threads, in ms: lavapipe's GPU work is CPU work, and
// a loaded machine disturbs it far less than the timestamps.
double process_cpu_ms();

// The world's cameras, or its directional lights, turned by `degrees` about the vertical, in place.
void turn_cameras(World& world, double degrees);
void turn_directional_lights(World& world, double degrees);

// Renders `frames` + 1 frames of `world` at width x height and returns, sorted, the GPU time of
// the passes `counts` accepts summed per frame, for all but the first (it JIT-compiles the
// pipelines). With `orbit_degrees`, the cameras turn by that much and back in turn every frame,
// so that nothing a node keeps for a still camera (gi.voxel's cones) is reused.
std::vector<double> sorted_pass_ms(Renderer& renderer, const World& world, uint32_t width, uint32_t height,
                                   uint32_t frames, const std::function<bool(const std::string&)>& counts,
                                   double orbit_degrees = 0.0);

}  // namespace lg::bench
