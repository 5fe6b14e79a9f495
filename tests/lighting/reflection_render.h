// Renders examples/reflections.json (SSR with the reflection probes' fallback), or for the planar
// configurations examples/planar-reflections.json (the same with gi.planar_reflection between the
// probes and lighting.ibl), in one of the reflection configurations issue 17 compares, through the
// library API on lavapipe, and reads back what an error against the path tracer's specular AOV
// needs: the lit and direct images and the G-buffer's material, plus the reflection passes' GPU
// time per frame. Configurations differ only in graph links and params, so this knows nothing of
// how a node captures or traces.
// Used by lumagraph-bench-reflections (tests/bench/reflection_bench.cpp).
#pragma once

#include <string>
#include <vector>

#include "graph/graph.h"
#include "nodes/gi/path_tracer/path_scene.h"
#include "runtime/scene/world.h"

namespace lg::test {

// Where lighting.ibl's specular radiance comes from.
// The planar ones (gi.planar_reflection) take the world's planar reflectors and, elsewhere, the
// environment (planar_with_ssr: SSR wins where it is confident) or the probes. voxel: gi.voxel's
// specular cone (one bounce of the main directional light) over the environment, through
// lighting.ibl's reflection_probes input.
enum class ReflectionSource {
  environment,
  probes,
  ssr,
  ssr_with_probes,
  planar,
  planar_with_probes,
  planar_with_ssr,
  voxel
};
const char* reflection_source_name(ReflectionSource source);

struct ReflectionConfig {
  ReflectionSource source = ReflectionSource::ssr_with_probes;
  bool parallax = true;        // gi.reflection_capture's parallax
  int face_size = 0;           // gi.reflection_capture's face_size; 0: the example's
  int max_steps = 0;           // lighting.ssr's max_steps; 0: the example's
  double ssr_scale = 0;        // lighting.ssr's resolution_scale; 0: the example's
  double planar_scale = 0;     // gi.planar_reflection's resolution_scale; 0: the example's
  double voxel_scale = 0;      // gi.voxel's resolution_scale; 0: the node's default
  bool voxel_sky = true;       // the example's SH linked into gi.voxel's sh (the sky's light in the voxels)
  std::string probe_params{};  // more gi.reflection_capture params as JSON members, e.g. "\"samples\": 64"
  std::string ssr_params{};    // more lighting.ssr params, likewise
};

// A short label, e.g. "ssr+probes steps=64 face=64" or "planar+ssr planar=0.50".
std::string config_label(const ReflectionConfig& config);

// The example with the configuration applied: the links from the sources not used are removed
// (into lighting.ibl, or the probes' into the planar node; the compiler then culls their nodes)
// and the params set.
Graph reflection_graph(const ReflectionConfig& config);

struct ReflectionFrame {
  std::vector<float> direct, lit, material;  // light.color, ibl.color, gbuf.gbuffer.material (RGBA)
  std::vector<float> ssr;                    // ssr.reflections (a: confidence) where SSR ran, else empty
  std::vector<double> reflection_gpu_ms;     // per frame: the probes', planar's, ssr's and voxel's passes summed
  std::vector<double> frame_gpu_ms;          // per frame: the whole command buffer
  std::vector<double> frame_wall_ms;         // per frame: render() on the host, captures included
  // Per frame: the process's CPU time (user and system, every thread) during render(). On
  // lavapipe that is the GPU work too, and unlike the timestamps it barely grows with the load
  // of a shared machine.
  std::vector<double> frame_cpu_ms;
  PathEnvironment environment;  // the plan's, for the reference
  size_t validation_messages = 0;
};

// `frames` frames (SSR reads the last frame's lit image from the second on and accumulates).
ReflectionFrame render_reflections(const World& world, uint32_t width, uint32_t height, const Graph& graph, int frames,
                                   bool validation);

}  // namespace lg::test
