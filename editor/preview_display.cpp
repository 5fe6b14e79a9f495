#include "editor/preview_display.h"

#include <algorithm>
#include <cmath>

#include "runtime/gpu/texel_codec.h"

namespace lg::editor {

QImage display_image(const PreviewImage& image, double exposure_ev, PreviewChannel channel) {
  QImage out(image.width, image.height, QImage::Format_RGB888);
  const float scale = float(std::exp2(exposure_ev));
  // Alpha is coverage, not light: neither exposed nor encoded.
  auto shown = [&](float v, int c) {
    if (c == 3 || image.encoding == PreviewEncoding::display) return std::clamp(v, 0.0f, 1.0f);
    return image.encoding == PreviewEncoding::colour ? linear_to_srgb(v * scale) : std::clamp(v * scale, 0.0f, 1.0f);
  };
  const bool grey = channel == PreviewChannel::rgb && image.channels == 1;
  for (int y = 0; y < image.height; ++y) {
    uchar* row = out.scanLine(y);
    for (int x = 0; x < image.width; ++x) {
      const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      uchar* q = row + x * 3;
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3])) {
        q[0] = 255, q[1] = 0, q[2] = 255;
        continue;
      }
      for (int c = 0; c < 3; ++c) {
        const int from = grey ? 0 : channel == PreviewChannel::rgb ? c : int(channel) - 1;
        q[c] = uchar(std::lround(shown(p[from], from) * 255.0f));
      }
    }
  }
  return out;
}

QString pixel_readout(const PreviewImage& image, int x, int y) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || image.empty()) return {};
  const float* p = &image.rgba[(size_t(y) * image.width + x) * 4];
  return QStringLiteral("x %1, y %2: %3 %4 %5 %6")
      .arg(x)
      .arg(y)
      .arg(double(p[0]), 0, 'g', 6)
      .arg(double(p[1]), 0, 'g', 6)
      .arg(double(p[2]), 0, 'g', 6)
      .arg(double(p[3]), 0, 'g', 6);
}

}  // namespace lg::editor
