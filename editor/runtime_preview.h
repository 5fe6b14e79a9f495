// The live preview on the runtime: compiles the edited graph for the embedded default world and
// renders one frame of its main output with the real kernels (lavapipe, or a GPU when there is
// one). Keeps its device and the last executor between edits; not thread-safe (AsyncPreview
// calls it from one worker thread).
#pragma once

#include <memory>

#include "editor/preview.h"

namespace lg {
class Renderer;
class World;
}  // namespace lg

namespace lg::editor {

class RuntimePreview : public PreviewRenderer {
 public:
  RuntimePreview();
  ~RuntimePreview() override;
  QImage render(const Graph& graph, QSize size, QString* error) override;

 private:
  std::unique_ptr<Renderer> renderer_;  // made on first use, on the thread that renders
  std::unique_ptr<World> world_;
};

}  // namespace lg::editor
