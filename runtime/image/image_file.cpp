#include "runtime/image/image_file.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>

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

}  // namespace

ImageData load_image(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw ImageFileError(path + ": error: no such image file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw ImageFileError(path + ": error: cannot read the image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
    throw ImageFileError(path + ": error: not a 2D image (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) + " channels)");
  const uint64_t pixels = uint64_t(spec.width) * uint64_t(spec.height);
  if (pixels > kMaxPixels)
    throw ImageFileError(path + ": error: " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                         " is larger than the limit of " + std::to_string(kMaxPixels) + " pixels");
  const int channels = std::min(spec.nchannels, 4);
  std::vector<float> read(pixels * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, read.data()))
    throw ImageFileError(path + ": error: the pixels cannot be read (truncated or corrupt?): " + in->geterror());
  ImageData out{uint32_t(spec.width), uint32_t(spec.height), std::vector<float>(pixels * 4, 0.0f)};
  for (uint64_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < channels; ++c) out.rgba[p * 4 + c] = read[p * channels + c];
    if (channels < 4) out.rgba[p * 4 + 3] = 1.0f;
    if (channels == 1) out.rgba[p * 4 + 1] = out.rgba[p * 4 + 2] = out.rgba[p * 4];  // grey
  }
  return out;
}

void save_image(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
  if (rgba.size() != uint64_t(width) * height * 4)
    throw ImageFileError(path + ": error: " + std::to_string(rgba.size()) + " floats do not make a " +
                         std::to_string(width) + "x" + std::to_string(height) + " RGBA image");
  const std::string ext = lower_extension(path);
  OIIO::TypeDesc type;
  int channels = 4;
  if (ext == ".png")
    type = OIIO::TypeDesc::UINT8;
  else if (ext == ".exr")
    type = OIIO::TypeDesc::HALF;
  else if (ext == ".hdr")
    type = OIIO::TypeDesc::FLOAT, channels = 3;
  else
    throw ImageFileError(path + ": error: unknown image extension '" + ext + "'; expected .png, .exr or .hdr");

  std::vector<float> pixels(uint64_t(width) * height * channels);
  for (uint64_t p = 0; p < uint64_t(width) * height; ++p)
    for (int c = 0; c < channels; ++c) pixels[p * channels + c] = rgba[p * 4 + c];

  // Same folder and extension, so the rename is atomic and OpenImageIO picks the same format.
  const fs::path target(path);
  const fs::path temporary = target.parent_path() / ("." + target.stem().string() + ".partial" + ext);
  auto out = OIIO::ImageOutput::create(temporary.string());
  if (!out) throw ImageFileError(path + ": error: cannot write this format: " + OIIO::geterror());
  OIIO::ImageSpec spec(int(width), int(height), channels, type);
  bool ok =
      out->open(temporary.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && out->close();
  std::error_code ec;
  if (!ok) {
    std::string why = out->geterror();
    fs::remove(temporary, ec);
    throw ImageFileError(path + ": error: writing failed: " + why);
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw ImageFileError(path + ": error: cannot replace the file: " + ec.message());
  }
}

}  // namespace lg
