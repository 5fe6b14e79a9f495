// Reading and writing image files: EXR and Radiance HDR (linear, float) and PNG (8- or 16-bit
// read, 8-bit written; taken as already display-encoded); a file is read by the format its first
// bytes name (image_formats.h). Pixels are float RGBA, rows top to
// bottom; ImageReader reads them straight into memory the caller owns (a staging buffer), so a
// large image is never held twice. Every failure — a missing, truncated or corrupt file, an
// unsupported format, a failed write — throws ImageFileError naming the file and what went
// wrong; saving is atomic (a temporary file renamed over the target), so a failed save never
// leaves half an image behind.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace lg {

class FormatReader;

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ImageData {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats a pixel; missing channels read as 0, alpha as 1
};

// An image file opened and its header checked (a 2D image within the size limit); the pixels
// are read on demand.
class ImageReader {
 public:
  explicit ImageReader(const std::string& path);  // throws ImageFileError
  ~ImageReader();
  ImageReader(const ImageReader&) = delete;
  ImageReader& operator=(const ImageReader&) = delete;

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Reads every pixel into `rgba` (width * height * 4 floats, laid out as ImageData::rgba); only
  // a PNG passes through a buffer of its own (its 8- or 16-bit pixels).
  void read_rgba(std::span<float> rgba);

 private:
  std::string path_;
  std::unique_ptr<FormatReader> input_;
  uint32_t width_ = 0, height_ = 0;
};

ImageData load_image(const std::string& path);

struct ImageSaveOptions {
  bool compress = true;     // EXR: zip; off is much faster to write and read for large scratch files
  bool full_float = false;  // EXR: 32-bit floats rather than half (references keep their precision)
};

// The format follows the extension: .png (8-bit, clamped to [0, 1]), .exr (half float unless
// full_float), .hdr.
void save_image(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba,
                const ImageSaveOptions& options = {});

}  // namespace lg
