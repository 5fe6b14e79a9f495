// The formats image_file.cpp reads and writes, one file each: PNG through libpng, OpenEXR
// through OpenEXR, Radiance RGBE (.hdr) our own. (glTF's textures are decoded by tinygltf, so
// no JPEG reader is needed: environments and references are EXR or HDR.) Opening a file
// reads and checks its header; read_rgba() then fills the caller's RGBA floats (rows top to
// bottom; grey goes to R, G and B; a missing alpha reads 1). Every failure throws
// ImageFileError naming the file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>

namespace lg {

// A C stream closed when it goes out of scope (libpng and the RGBE code read and write through one).
struct CFile {
  std::FILE* handle;
  CFile(const std::string& path, const char* mode) : handle(std::fopen(path.c_str(), mode)) {}
  ~CFile() {
    if (handle) std::fclose(handle);
  }
  CFile(const CFile&) = delete;
  CFile& operator=(const CFile&) = delete;
};

class FormatReader {
 public:
  virtual ~FormatReader() = default;
  virtual void read_rgba(std::span<float> rgba) = 0;  // width * height * 4 floats
  uint32_t width = 0, height = 0;
};

std::unique_ptr<FormatReader> open_png(const std::string& path);
std::unique_ptr<FormatReader> open_exr(const std::string& path);
std::unique_ptr<FormatReader> open_rgbe(const std::string& path);

// `rgba` holds width * height * 4 floats. PNG: 8-bit RGBA clamped to [0, 1]; EXR: RGBA, half
// floats unless full_float, zip-compressed when compress; RGBE: RGB. A failure throws a
// std::exception saying why (save_image() names the file).
void write_png(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba);
void write_exr(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba, bool compress,
               bool full_float);
void write_rgbe(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba);

}  // namespace lg
