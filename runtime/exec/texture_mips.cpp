// mip_chain(): see texture_mips.h.
#include "runtime/exec/texture_mips.h"

#include <algorithm>
#include <bit>

namespace lg {

uint32_t mip_count(uint32_t width, uint32_t height) {
  return static_cast<uint32_t>(std::bit_width(std::max({width, height, 1u})));
}

std::vector<std::vector<float>> mip_chain(const std::vector<float>& rgba, uint32_t width, uint32_t height) {
  std::vector<std::vector<float>> levels{rgba};
  const uint32_t count = mip_count(width, height);
  for (uint32_t level = 1; level < count; ++level) {
    const std::vector<float>& src = levels.back();
    const uint32_t w = std::max(1u, width >> 1), h = std::max(1u, height >> 1);
    std::vector<float> dst(size_t{w} * h * 4);
    for (uint32_t y = 0; y < h; ++y) {
      // The source rows and columns this texel covers: [y * height / h, ceil((y + 1) * height / h)).
      const uint32_t y0 = y * height / h, y1 = ((y + 1) * height + h - 1) / h;
      for (uint32_t x = 0; x < w; ++x) {
        const uint32_t x0 = x * width / w, x1 = ((x + 1) * width + w - 1) / w;
        float sum[4] = {};
        for (uint32_t sy = y0; sy < y1; ++sy)
          for (uint32_t sx = x0; sx < x1; ++sx)
            for (int c = 0; c < 4; ++c) sum[c] += src[(size_t{sy} * width + sx) * 4 + c];
        const float n = static_cast<float>((y1 - y0) * (x1 - x0));
        for (int c = 0; c < 4; ++c) dst[(size_t{y} * w + x) * 4 + c] = sum[c] / n;
      }
    }
    levels.push_back(std::move(dst));
    width = w;
    height = h;
  }
  return levels;
}

}  // namespace lg
