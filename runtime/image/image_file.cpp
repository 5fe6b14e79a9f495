#include "runtime/image/image_file.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include "runtime/image/exr_header_check.h"

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

struct ImageReader::Input {
  std::unique_ptr<OIIO::ImageInput> image;
};

ImageReader::ImageReader(const std::string& path) : path_(path), input_(std::make_unique<Input>()) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw ImageFileError(path + ": error: no such image file");
  check_exr_header(path, kMaxPixels);
  // The reader of the file's extension alone, made from the extension (a file name lets
  // OpenImageIO probe the file and try other formats): when it failed, ImageInput::open() went on
  // to try every format OpenImageIO knows, which cost tens of milliseconds a file and answered a
  // corrupt EXR with "could not find a format reader". No extension: OpenImageIO guesses.
  const std::string ext = lower_extension(path);
  input_->image = OIIO::ImageInput::create(ext.size() > 1 ? ext.substr(1) : path);
  OIIO::ImageSpec opened;
  if (!input_->image || !input_->image->open(path, opened))
    throw ImageFileError(
        path + ": error: cannot read the image: " + (input_->image ? input_->image->geterror() : OIIO::geterror()));
  const OIIO::ImageSpec& spec = input_->image->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
    throw ImageFileError(path + ": error: not a 2D image (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) + " channels)");
  const uint64_t pixels = uint64_t(spec.width) * uint64_t(spec.height);
  if (pixels > kMaxPixels)
    throw ImageFileError(path + ": error: " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                         " is larger than the limit of " + std::to_string(kMaxPixels) + " pixels");
  width_ = uint32_t(spec.width), height_ = uint32_t(spec.height);
}

ImageReader::~ImageReader() = default;

void ImageReader::read_rgba(std::span<float> rgba) {
  const uint64_t pixels = uint64_t(width_) * height_;
  if (rgba.size() != pixels * 4)
    throw ImageFileError(path_ + ": error: " + std::to_string(rgba.size()) + " floats cannot hold its " +
                         std::to_string(width_) + "x" + std::to_string(height_) + " RGBA pixels");
  OIIO::ImageInput& in = *input_->image;
  const OIIO::ImageSpec& spec = in.spec();
  const int channels = std::min(spec.nchannels, 4);
  // Up to four channels land at their place in each RGBA pixel; the others are filled below.
  const OIIO::stride_t pixel_stride = 4 * sizeof(float), row_stride = pixel_stride * width_;
  bool ok = true;
  if (spec.tile_width == 0 && spec.nchannels <= 4) {
    // A row at a time: OpenImageIO converts a row through a buffer of one native row, where
    // read_scanlines and read_image convert through one of 64 MiB whatever the rows asked for.
    for (uint32_t y = 0; ok && y < height_; ++y)
      ok = in.read_scanline(spec.y + int(y), 0, OIIO::TypeDesc::FLOAT, rgba.data() + uint64_t(y) * width_ * 4,
                            pixel_stride);
  } else {
    ok = in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, rgba.data(), pixel_stride, row_stride);
  }
  if (!ok) throw ImageFileError(path_ + ": error: the pixels cannot be read (truncated or corrupt?): " + in.geterror());
  if (channels == 4) return;
  for (uint64_t p = 0; p < pixels; ++p) {
    float* texel = &rgba[p * 4];
    if (channels == 1) texel[1] = texel[2] = texel[0];  // grey
    if (channels == 2) texel[2] = 0.0f;
    texel[3] = 1.0f;
  }
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
  OIIO::TypeDesc type;
  int channels = 4;
  if (ext == ".png")
    type = OIIO::TypeDesc::UINT8;
  else if (ext == ".exr")
    type = options.full_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF;
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
  if (ext == ".exr") spec.attribute("compression", options.compress ? "zip" : "none");
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
