// The seam for the live preview: something that renders a graph to an image. The runtime's
// executor and the node kernels are not part of the editor yet; when they are, an
// implementation that compiles the graph and runs one frame on the runtime plugs in here
// (MainWindow::set_preview) and the editor shows its image in the Preview dock after each edit.
#pragma once

#include <QImage>
#include <QString>

#include "graph/graph.h"

namespace lg::editor {

class PreviewRenderer {
 public:
  virtual ~PreviewRenderer() = default;
  // An image of the graph's output at about `size`, or a null image with `error` set.
  virtual QImage render(const Graph& graph, QSize size, QString* error) = 0;
};

}  // namespace lg::editor
