// OpenEXR through its C++ library, after image_file.cpp checked the header (exr_header_check.h);
// the pixels go straight into the caller's floats, OpenEXR converting from half or uint. The
// channels R, G, B and A are read (missing ones 0, alpha 1), or Y as grey where none of R, G and
// B is there (a luminance-chroma file reads as its luminance); a layered file whose channels
// are all named "layer.R" and so on is refused naming the channels it lacks.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <vector>

#include "runtime/image/image_file.h"
#include "runtime/image/image_formats.h"

namespace lg {
namespace {

class ExrReader final : public FormatReader {
 public:
  explicit ExrReader(const std::string& path) : path_(path) {
    try {
      file_ = std::make_unique<Imf::InputFile>(path.c_str());
    } catch (const std::exception& e) {
      throw ImageFileError(path + ": error: cannot read the image: " + e.what());
    }
    const Imf::ChannelList& channels = file_->header().channels();
    grey_ = !channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B");
    if (grey_ && !channels.findChannel("Y"))
      throw ImageFileError(path + ": error: the EXR has none of the channels R, G, B or Y");
    const Imath::Box2i window = file_->header().dataWindow();
    width = uint32_t(int64_t(window.max.x) - window.min.x + 1);
    height = uint32_t(int64_t(window.max.y) - window.min.y + 1);
  }

  void read_rgba(std::span<float> rgba) override {
    const Imath::Box2i window = file_->header().dataWindow();
    const size_t pixel = 4 * sizeof(float), row = pixel * width;
    char* base = reinterpret_cast<char*>(rgba.data());
    const auto slice = [&](int offset, double fill) {
      return Imf::Slice::Make(Imf::FLOAT, base + offset * sizeof(float), window, pixel, row, 1, 1, fill);
    };
    Imf::FrameBuffer frame;
    if (grey_) {
      frame.insert("Y", slice(0, 0.0));
    } else {
      frame.insert("R", slice(0, 0.0));
      frame.insert("G", slice(1, 0.0));
      frame.insert("B", slice(2, 0.0));
    }
    frame.insert("A", slice(3, 1.0));
    try {
      file_->setFrameBuffer(frame);
      file_->readPixels(window.min.y, window.max.y);
    } catch (const std::exception& e) {
      throw ImageFileError(path_ + ": error: the pixels cannot be read (truncated or corrupt?): " + e.what());
    }
    if (grey_)
      for (size_t p = 0; p < size_t(width) * height; ++p) rgba[4 * p + 1] = rgba[4 * p + 2] = rgba[4 * p];
  }

 private:
  std::string path_;
  std::unique_ptr<Imf::InputFile> file_;
  bool grey_ = false;
};

}  // namespace

std::unique_ptr<FormatReader> open_exr(const std::string& path) {
  return std::make_unique<ExrReader>(path);
}

void write_exr(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba, bool compress,
               bool full_float) {
  Imf::Header header{int(width), int(height)};
  header.compression() = compress ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
  // OpenEXR converts on reading only: a half file is written from halves.
  std::vector<Imath::half> halves(full_float ? 0 : rgba.size());
  for (size_t i = 0; i < halves.size(); ++i) halves[i] = Imath::half(rgba[i]);
  const Imf::PixelType type = full_float ? Imf::FLOAT : Imf::HALF;
  const size_t size = full_float ? sizeof(float) : sizeof(Imath::half);
  // Only read from: OpenEXR's Slice takes a non-const pointer for input and output alike.
  char* data = full_float ? const_cast<char*>(reinterpret_cast<const char*>(rgba.data()))
                          : reinterpret_cast<char*>(halves.data());
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(type));
    frame.insert(names[c], Imf::Slice(type, data + c * size, 4 * size, 4 * size * width));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(int(height));
}

}  // namespace lg
