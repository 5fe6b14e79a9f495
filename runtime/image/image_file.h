// Reading and writing image files with OpenImageIO: EXR and HDR (linear, float) and PNG (8-bit,
// values taken as already display-encoded). Pixels are float RGBA, rows top to bottom. Every
// failure — a missing, truncated or corrupt file, an unsupported format, a failed write —
// throws ImageFileError naming the file and what went wrong; saving is atomic (a temporary
// file renamed over the target), so a failed save never leaves half an image behind.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace lg {

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImageData {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats a pixel; missing channels read as 0, alpha as 1
};

ImageData load_image(const std::string& path);

// The format follows the extension: .png (8-bit, clamped to [0, 1]), .exr (half float), .hdr.
void save_image(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba);

}  // namespace lg
