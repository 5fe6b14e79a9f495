#include "editor/runtime_preview.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "api/renderer.h"
#include "runtime/scene/default_world.h"

namespace lg::editor {

RuntimePreview::RuntimePreview() = default;
RuntimePreview::~RuntimePreview() = default;

QImage RuntimePreview::render(const Graph& graph, QSize size, QString* error) {
  try {
    if (!renderer_) {
      renderer_ = std::make_unique<Renderer>();
      world_ = std::make_unique<World>(default_world());
    }
    renderer_->set_graph(graph);
    const FrameSize frame{uint32_t(std::max(size.width(), 16)), uint32_t(std::max(size.height(), 16))};
    renderer_->render(*world_, frame);
    const std::vector<float> rgba = renderer_->read_output();
    // The main output is display-encoded (ldr) in the usual graphs; linear outputs show clamped.
    QImage image(int(frame.width), int(frame.height), QImage::Format_RGB888);
    for (uint32_t y = 0; y < frame.height; ++y) {
      uchar* row = image.scanLine(int(y));
      for (uint32_t x = 0; x < frame.width * 3; ++x) {
        const float v = rgba[(y * frame.width + x / 3) * 4 + x % 3];
        row[x] = uchar(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
      }
    }
    return image;
  } catch (const std::exception& e) {
    *error = QString::fromStdString(e.what());
    return {};
  }
}

}  // namespace lg::editor
