// Renders a G-buffer and one occlusion node (occlusion.gtao, its history linked back,
// occlusion.ssao or occlusion.bake) through the library API on lavapipe, and reads back what the references and
// the error statistics need: the occlusion after the first and the last frame, the G-buffer's
// depth and normals, the frame's SceneView, and the occlusion node's GPU time per frame (its
// passes' timestamps). Shared by tests/occlusion and lumagraph-bench-ao.
#pragma once

#include <string>
#include <vector>

#include "graph/graph.h"
#include "nodes/occlusion/reference/height_field_reference.h"
#include "runtime/scene/scene_view.h"
#include "runtime/scene/world.h"

namespace lg::test {

struct AoRender {
  std::vector<float> first_ao;      // float RGBA after frame 1 (no history yet)
  std::vector<float> last_ao;       // after the last frame (temporal accumulation, for GTAO)
  std::vector<float> bent_normals;  // GTAO's or the bake's, after the last frame (empty for SSAO)
  GbufferReadback gbuffer;
  SceneView view;                    // the last frame's
  std::vector<double> ao_gpu_ms;     // per frame, the occlusion node's passes summed
  std::vector<double> frame_gpu_ms;  // per frame, the whole command buffer
  size_t validation_messages = 0;
};

// `node` is the occlusion node's JSON object with id "ao", e.g.
// { "id": "ao", "type": "occlusion.gtao", "params": { "quality": "high" } }.
Graph occlusion_graph(const std::string& node);

struct AoRenderOptions {
  int frames = 1;
  bool validation = true;  // off in benchmarks: the timings are of the driver, not the layer
};

AoRender render_occlusion(const World& world, uint32_t width, uint32_t height, const std::string& node,
                          const AoRenderOptions& options = {});

// The example worlds by file name (examples/worlds/NAME.json, relative to the source root), with
// ../shared/data as an extra asset root for the Stanford bunny.
World load_example_world(const std::string& name);

// Whether ../shared/data holds the Stanford bunny that the stanford-bunny world needs.
bool have_bunny();

}  // namespace lg::test
