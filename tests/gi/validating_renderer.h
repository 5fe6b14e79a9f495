// A Renderer for the one-bounce nodes' GPU tests (gi.lpv, gi.voxel): validation on, and every
// transient its own memory, so each node output can be read back after the frame.
#pragma once

#include <memory>

#include "api/renderer.h"

namespace lg::test {

inline std::unique_ptr<Renderer> make_renderer(const Graph& graph) {
  RendererOptions options;
  options.device.validation = true;
  options.alias = false;
  auto renderer = std::make_unique<Renderer>(options);
  renderer->set_graph(graph);
  return renderer;
}

}  // namespace lg::test
