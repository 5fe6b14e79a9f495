// The live preview on the runtime: compiles the edited graph for the embedded default world (or
// a scene file, glTF or OBJ given at construction),
// renders one frame with the real kernels (lavapipe, or a GPU when there is one) and reads back
// the chosen port: the main output, or any node output, which it adds to the graph's outputs
// so that the node is not culled and its resource lives to the end of the frame (memory
// aliasing stays on). Keeps its device and the last executor between edits, and between requests
// for the same graph (node positions aside) renders on the same one, so that a dynamic probe
// volume goes on converging; after each frame it copies the probe volumes' probes (live_probes.h).
// Not thread-safe (AsyncPreview calls it from one worker thread).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/preview.h"

namespace lg {
class Renderer;
class World;
}  // namespace lg

namespace lg::editor {

class RuntimePreview : public PreviewRenderer {
 public:
  // `scene`: a file for runtime/scene/load_world.h, whose paths may point into its own folder
  // and into `asset_roots`; empty: the embedded default world.
  // The world is loaded here, so that scene_summary() answers before the first render; one that
  // fails to load is render()'s error.
  explicit RuntimePreview(const std::string& scene = {}, const std::vector<std::string>& asset_roots = {});
  ~RuntimePreview() override;
  PreviewImage render(const Graph& graph, QSize size, const PreviewPort& port, QString* error) override;
  SceneSummary scene_summary() const override;

 private:
  LiveProbes live_probes(const Graph& graph);

  std::unique_ptr<Renderer> renderer_;  // made on first use, on the thread that renders
  std::unique_ptr<World> world_;        // null when it failed to load
  std::string load_error_;
  std::string scene_name_;                 // for saved probes: the file, or "<default world>"
  std::string graph_text_;                 // the graph the renderer has, positions left out
  std::optional<uint64_t> geometry_hash_;  // of the world, for saved probes
  LiveProbeCollector probes_;
};

// The graph as the preview renders it: `port` (when not the main output) among its outputs.
Graph graph_showing(Graph graph, const PreviewPort& port);

}  // namespace lg::editor
