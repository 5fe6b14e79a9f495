// lumagraph-bench-scene-view: what make_scene_view() costs once per frame (api/renderer.cpp calls
// it with last frame's view) on examples/worlds/stanford-bunny.json (the bunny of
// ../shared/data and a floor quad), on the embedded default world, and on one sphere of 16k to
// 4M triangles (how the cost grows with the world's mesh data). Time per call from Google
// Benchmark; heap allocations and bytes allocated per call (heap_tracker.h) as counters, from one
// call outside the timed loop. Run: ./build/lumagraph-bench-scene-view (add
// --benchmark_out=scene_view.csv --benchmark_out_format=csv for a CSV).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "runtime/scene/default_world.h"
#include "runtime/scene/load_world.h"
#include "runtime/scene/make_scene_view.h"
#include "runtime/scene/mesh_generators.h"
#include "tests/bench/heap_tracker.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

const fs::path shared_data = fs::path(LUMAGRAPH_SOURCE_DIR) / ".." / "shared" / "data";

// The bunny world reaches ../shared/data through an asset root, as SceneFile.ExampleWorldsLoad does.
World bunny_world() {
  fs::path examples = fs::path(LUMAGRAPH_SOURCE_DIR) / "examples" / "worlds";
  WorldLoadOptions options;
  options.asset_roots.roots = {examples.string(), shared_data.string()};
  return load_world((examples / "stanford-bunny.json").string(), options);
}

void frames(benchmark::State& state, const World& world) {
  const float aspect = 16.0f / 9.0f;
  SceneView previous = make_scene_view(world, aspect);
  {
    bench::HeapScope heap;
    SceneView view = make_scene_view(world, aspect, &previous);
    bench::HeapUsage usage = heap.usage();
    state.counters["allocs_per_frame"] = static_cast<double>(usage.allocations);
    state.counters["peak_heap_bytes"] = static_cast<double>(usage.peak_bytes);
  }
  for (auto _ : state) {
    SceneView view = make_scene_view(world, aspect, &previous);
    benchmark::DoNotOptimize(view.draws.data());
    previous = std::move(view);
  }
  size_t triangles = 0;
  for (const auto& draw : previous.draws) triangles += previous.mesh_of(draw).indices.size() / 3;
  state.counters["drawn_triangles"] = static_cast<double>(triangles);
}

void BM_SceneViewBunny(benchmark::State& state) {
  if (!fs::exists(shared_data / "mesh" / "bunny.obj")) {
    state.SkipWithError("no ../shared/data/mesh/bunny.obj");
    return;
  }
  static const World world = bunny_world();
  frames(state, world);
}

void BM_SceneViewDefaultWorld(benchmark::State& state) {
  static const World world = default_world();
  frames(state, world);
}

// A sphere of `segments` x segments/2 quads, drawn once with the default camera and no lights.
void BM_SceneViewSphere(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  World world;
  Entity e = world.create("sphere");
  world.add<Transform>(e, {});
  world.add<MeshRenderer>(e, {world.add_mesh(make_sphere(1.0f, segments, segments / 2)), -1});
  frames(state, world);
}

BENCHMARK(BM_SceneViewBunny)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SceneViewDefaultWorld)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SceneViewSphere)->Arg(128)->Arg(512)->Arg(2048)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace lg

BENCHMARK_MAIN();
