#include "runtime/image/image_file.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "runtime/image/exr_header_check.h"
#include "runtime/image/image_formats.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

// Files larger than this are refused before any pixels are read (8192 x 8192 RGBA floats).
constexpr uint64_t kMaxPixels = uint64_t{8192} * 8192;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// The reader of the format the file's first bytes name, whatever its extension says.
std::unique_ptr<FormatReader> open_by_signature(const std::string& path) {
  char magic[8] = {};
  std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
  if (std::memcmp(magic, "\x89PNG\r\n\x1a\n", 8) == 0) return open_png(path);
  if (std::memcmp(magic, "\x76\x2f\x31\x01", 4) == 0) {
    check_exr_header(path, kMaxPixels);
    return open_exr(path);
  }
  if (std::memcmp(magic, "#?", 2) == 0) return open_rgbe(path);
  throw ImageFileError(path + ": error: cannot read the image: its first bytes are not those of a PNG, OpenEXR "
                              "or Radiance HDR file");
}

}  // namespace

ImageReader::ImageReader(const std::string& path) : path_(path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw ImageFileError(path + ": error: no such image file");
  input_ = open_by_signature(path);
  const uint64_t pixels = uint64_t(input_->width) * input_->height;
  if (pixels == 0) throw ImageFileError(path + ": error: the image has no pixels");
  if (pixels > kMaxPixels)
    throw ImageFileError(path + ": error: " + std::to_string(input_->width) + "x" + std::to_string(input_->height) +
                         " is larger than the limit of " + std::to_string(kMaxPixels) + " pixels");
  width_ = input_->width, height_ = input_->height;
}

ImageReader::~ImageReader() = default;

void ImageReader::read_rgba(std::span<float> rgba) {
  if (rgba.size() != uint64_t(width_) * height_ * 4)
    throw ImageFileError(path_ + ": error: " + std::to_string(rgba.size()) + " floats cannot hold its " +
                         std::to_string(width_) + "x" + std::to_string(height_) + " RGBA pixels");
  input_->read_rgba(rgba);
}

ImageData load_image(const std::string& path) {
  ImageReader reader(path);
  ImageData out{reader.width(), reader.height(), std::vector<float>(uint64_t(reader.width()) * reader.height() * 4)};
  reader.read_rgba(out.rgba);
  return out;
}

void save_image(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba,
                const ImageSaveOptions& options) {
  if (rgba.size() != uint64_t(width) * height * 4)
    throw ImageFileError(path + ": error: " + std::to_string(rgba.size()) + " floats do not make a " +
                         std::to_string(width) + "x" + std::to_string(height) + " RGBA image");
  const std::string ext = lower_extension(path);
  if (ext != ".png" && ext != ".exr" && ext != ".hdr")
    throw ImageFileError(path + ": error: unknown image extension '" + ext + "'; expected .png, .exr or .hdr");
  // A temporary file in the same folder, renamed over the target: the rename is atomic.
  const fs::path target(path);
  const fs::path temporary = target.parent_path() / ("." + target.stem().string() + ".partial" + ext);
  std::error_code ec;
  try {
    if (ext == ".png") write_png(temporary.string(), width, height, rgba);
    if (ext == ".exr") write_exr(temporary.string(), width, height, rgba, options.compress, options.full_float);
    if (ext == ".hdr") write_rgbe(temporary.string(), width, height, rgba);
  } catch (const std::exception& e) {
    fs::remove(temporary, ec);
    throw ImageFileError(path + ": error: writing failed: " + e.what());
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw ImageFileError(path + ": error: cannot replace the file: " + ec.message());
  }
}

}  // namespace lg
