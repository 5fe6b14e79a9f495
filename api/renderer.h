// The library API a game uses: load a graph file, render frames of a world into images the
// host samples or presents. The Renderer compiles the graph against the world's scene summary
// and the frame size, and compiles again only when either (or the graph) changes; static results
// (an environment convolution, a lookup table) are cached across frames, and across recompiles
// where their cache keys are unchanged.
//
//   lg::Renderer renderer;                          // its own Vulkan device (or the host's)
//   renderer.load_graph("graphs/deferred.json");    // throws GraphError with every error
//   lg::World world = lg::load_world("level.json", lg::renderer_world_options("level.json"));
//   for (;;) {
//     renderer.render(world, {1920, 1080});         // one frame; returns its stats
//     VkImage image = renderer.output_image().handle();  // in output_layout()
//   }
//
// A failed load_graph() or reload_graph() keeps the last good graph running (hot reload).
// Pipelines are shared by every plan the renderer compiles, and their driver cache is saved to
// disk after the first frame of each plan that made new ones and when the renderer goes. Static
// results are kept on disk beside it (runtime/exec/static_results_store.h): written after the
// first frame of a plan that ran its static passes, loaded by a later run's plan of the same key.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "graph/asset_paths.h"
#include "graph/compiler.h"
#include "graph/graph.h"
#include "runtime/exec/executor.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/exec/static_results_store.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/pipeline_cache_store.h"
#include "runtime/scene/scene_view.h"
#include "runtime/scene/world.h"

namespace lg {

// Every error of a graph file (or of compiling it for a scene), one per line as
// file:line:col: error: message (json pointer).
class GraphError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RendererOptions {
  ContextOptions device{};           // a device of its own: validation, device name
  const HostDevice* host = nullptr;  // or the host engine's device, which it keeps owning
  AssetRoots asset_roots{};          // where file paths in graphs may point
  bool alias = true;                 // false: every transient resource keeps its own memory
  bool keep_optional_outputs = false;  // write optional outputs nothing links (a dump: gi.lpv's volume)
  // The driver's pipeline cache and the plans' static results kept on disk between runs
  // (runtime/gpu/pipeline_cache_store.h, runtime/exec/static_results_store.h), in
  // `pipeline_cache_folder` or, when that is empty, $XDG_CACHE_HOME/lumagraph (~/.cache/...).
  // LUMAGRAPH_PIPELINE_CACHE=off in the environment turns both off too.
  bool pipeline_cache_on_disk = true;
  std::string pipeline_cache_folder{};
  // The most bytes of static results the folder keeps: the least recently used go first.
  uint64_t static_results_max_bytes = StaticResultsStore::default_max_bytes;
};

// What temporal nodes need of a frame beyond the world (post.exposure adapts over it): the time
// since the previous frame and whether the camera cut, which restarts their history. `jitter`
// sets the projection's sub-pixel offset in pixels of the frame (a supersampled reference, a
// host with its own sequence); unset, a graph with post.taa jitters with Halton (2, 3) and
// other graphs do not jitter (runtime/scene/camera_jitter.h).
struct FrameTiming {
  float seconds = 1.0f / 60.0f;
  bool camera_cut = false;
  std::optional<glm::vec2> jitter{};
};

class Renderer {
 public:
  explicit Renderer(const RendererOptions& options = {});
  ~Renderer();

  Context& context() { return *context_; }

  void load_graph(const std::string& path);
  // A graph already in memory (an editor's); `file` names it in messages and anchors paths.
  void set_graph(Graph graph);
  // Reads the last loaded file again; on errors throws and keeps the graph that ran before.
  void reload_graph();

  // Renders one frame; compiles first when the graph, the world's scene summary or the frame
  // size changed since the last frame. Throws GraphError when the graph does not compile for
  // this scene, ExecutorError or GpuError when the frame fails.
  const FrameStats& render(const World& world, FrameSize frame, FrameTiming timing = {});

  // Valid after the first render().
  const Plan& plan() const;
  Executor& executor();
  const SceneView& scene_view() const { return view_; }
  // What output node `name` ("main" unless the graph names it otherwise) shows, in its layout.
  Image& output_image(std::string_view name = "main");
  VkImageLayout output_layout(std::string_view name = "main");
  std::vector<float> read_output(std::string_view name = "main");  // float RGBA, rows top down

  // The pipeline cache on disk; null when it is off (options, environment, no cache folder).
  const PipelineCacheStore* pipeline_cache_store() const { return pipeline_store_.get(); }
  // The static results on disk; null when the disk cache is off.
  const StaticResultsStore* static_results_store() const { return static_store_.get(); }
  // Warnings since the last call (an ignored or unsaved cache file), one line each.
  std::vector<std::string> take_warnings();

 private:
  void compile_for(const SceneSummary& summary, FrameSize frame);

  RendererOptions options_;
  std::unique_ptr<Context> context_;
  std::unique_ptr<PipelineCacheStore> pipeline_store_;  // after the context: goes before it
  std::unique_ptr<StaticResultsStore> static_store_;
  uint64_t static_key_ = 0;  // the executor's plan's, in static_store_; 0: nothing kept
  std::optional<Graph> graph_;
  bool graph_changed_ = false;
  std::optional<SceneSummary> summary_;
  FrameSize frame_{};
  SceneView view_;
  bool has_view_ = false;
  std::unique_ptr<GpuScene> gpu_scene_;
  std::unique_ptr<Executor> executor_;
  FrameStats stats_;
};

}  // namespace lg
