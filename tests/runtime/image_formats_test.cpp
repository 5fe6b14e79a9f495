// The image formats (runtime/image/image_formats.h): what each keeps of a float image written and
// read back, that a file is read by its first bytes, and how broken Radiance HDR files (whose
// reader is ours) are refused.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "runtime/image/image_file.h"

namespace lg {
namespace {

namespace fs = std::filesystem;

struct Folder {
  fs::path path = fs::temp_directory_path() / ("lumagraph-image-formats-test-" + std::to_string(::getpid()));
  Folder() { fs::create_directories(path); }
  ~Folder() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

std::string bytes_of(const std::string& path) {
  std::stringstream bytes;
  bytes << std::ifstream(path, std::ios::binary).rdbuf();
  return bytes.str();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string open_error(const std::string& path) {
  try {
    load_image(path);
  } catch (const ImageFileError& e) {
    return e.what();
  }
  return "loaded";
}

// A w x h image of values from 1e-3 to 1e4 (HDR) or 0 to 1 (display), alpha 0 to 1.
std::vector<float> test_image(uint32_t w, uint32_t h, bool display) {
  std::vector<float> rgba(size_t(w) * h * 4);
  for (size_t i = 0; i < rgba.size(); ++i) {
    const float t = float((i * 37) % 101) / 100.0f;
    rgba[i] = i % 4 == 3 || display ? t : std::pow(10.0f, 7.0f * t - 3.0f);
  }
  return rgba;
}

// Half an 8-bit step, and the float rounding of values that sit exactly on one (37 / 100 * 255).
constexpr float kHalfStep = 0.5f / 255 + 1e-6f;

struct Case {
  const char* name;
  ImageSaveOptions options;
  bool display;
  bool alpha;           // kept
  float relative;       // of each pixel's largest colour component
};

TEST(ImageFormats, EachFormatKeepsWhatItsPrecisionAllows) {
  Folder folder;
  const Case cases[] = {
      {"half.exr", {}, false, true, 1.0f / 2048},  // half: 11 significant bits
      {"float.exr", {.full_float = true}, false, true, 0.0f},
      {"plain.exr", {.compress = false}, false, true, 1.0f / 2048},
      {"rgbe.hdr", {}, false, false, 1.0f / 128},  // 8-bit mantissas under the shared exponent
      {"display.png", {}, true, true, kHalfStep},  // absolute: values in [0, 1]
  };
  for (uint32_t width : {13u, 5u})  // RGBE: run-length encoded from width 8, flat below
    for (const Case& c : cases) {
      const std::vector<float> in = test_image(width, 3, c.display);
      const std::string path = folder.file(std::to_string(width) + c.name);
      save_image(path, width, 3, in, c.options);
      const ImageData out = load_image(path);
      ASSERT_EQ(out.width, width);
      ASSERT_EQ(out.height, 3u);
      for (size_t p = 0; p < size_t(width) * 3; ++p) {
        const float largest = c.display ? 1.0f : std::max({in[4 * p], in[4 * p + 1], in[4 * p + 2]});
        for (int k = 0; k < 4; ++k) {
          const float want = k < 3 || c.alpha ? in[4 * p + k] : 1.0f;
          const float bound = k == 3 ? (c.display ? kHalfStep : 1.0f / 2048) : c.relative * largest;
          EXPECT_LE(std::abs(out.rgba[4 * p + k] - want), bound) << c.name << " width " << width << " pixel " << p
                                                                 << " channel " << k;
        }
      }
    }
}

TEST(ImageFormats, NonFiniteAndNegativeValuesAreWrittenAsZeroOrTheirLimit) {
  Folder folder;
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> in = {nan, -1.0f, inf, 1.0f, 1e38f, 0.5f, 2.0f, 1.0f};
  save_image(folder.file("a.hdr"), 2, 1, in);
  const ImageData hdr = load_image(folder.file("a.hdr"));
  EXPECT_EQ(hdr.rgba[0], 0.0f);  // NaN
  EXPECT_EQ(hdr.rgba[1], 0.0f);  // negative
  EXPECT_EQ(hdr.rgba[2], 0.0f);  // Inf: not finite, so 0 like NaN
  EXPECT_NEAR(hdr.rgba[4] / 1e38f, 1.0f, 1.0f / 128);
  save_image(folder.file("a.png"), 2, 1, in);
  const ImageData png = load_image(folder.file("a.png"));
  EXPECT_EQ(png.rgba[0], 0.0f);  // NaN
  EXPECT_EQ(png.rgba[1], 0.0f);
  EXPECT_EQ(png.rgba[2], 1.0f);
  EXPECT_EQ(png.rgba[4], 1.0f);
}

TEST(ImageFormats, AFileIsReadByItsFirstBytesNotItsExtension) {
  Folder folder;
  const std::vector<float> in = test_image(4, 2, false);
  save_image(folder.file("real.exr"), 4, 2, in, {.full_float = true});
  fs::rename(folder.file("real.exr"), folder.file("named.hdr"));
  EXPECT_EQ(load_image(folder.file("named.hdr")).rgba, in);
  write_bytes(folder.file("text.exr"), "P3\n1 1\n255\n0 0 0\n");
  EXPECT_EQ(open_error(folder.file("text.exr")),
            folder.file("text.exr") + ": error: cannot read the image: its first bytes are not those of a PNG, "
                                      "OpenEXR or Radiance HDR file");
}

TEST(ImageFormats, RadianceRowsStoredBottomUpAreTurnedOver) {
  Folder folder;
  // Two rows of one pixel, flat: the first stored is the bottom one. 128 * 2^(129 - 136) = 1.
  write_bytes(folder.file("up.hdr"),
              "#?RADIANCE\n\n+Y 2 +X 1\n" + std::string("\x80\x00\x00\x81", 4) + std::string("\x00\x80\x00\x81", 4));
  const ImageData image = load_image(folder.file("up.hdr"));
  EXPECT_EQ(image.rgba, (std::vector<float>{0, 1, 0, 1, 1, 0, 0, 1}));
}

TEST(ImageFormats, BrokenRadianceFilesAreRefusedNamingTheFileAndWhy) {
  Folder folder;
  save_image(folder.file("good.hdr"), 16, 4, test_image(16, 4, false));
  const std::string good = bytes_of(folder.file("good.hdr"));
  const auto error_of = [&](const std::string& name, const std::string& bytes) {
    write_bytes(folder.file(name), bytes);
    const std::string message = open_error(folder.file(name));
    return message.substr(0, std::min(message.size(), folder.file(name).size() + 9)) == folder.file(name) + ": error: "
               ? message.substr(folder.file(name).size() + 9)
               : message;
  };
  EXPECT_EQ(error_of("cut.hdr", good.substr(0, good.size() - 10)),
            "the pixels cannot be read (truncated or corrupt?): the file ends inside scan line 3 of 4");
  const size_t first_run = good.find("+X 16\n") + 6 + 4;  // after the first scan line's 2, 2, 0, 16
  std::string long_run = good;
  long_run[first_run] = char(120);  // 120 literal bytes in a 16-pixel line
  EXPECT_EQ(error_of("run.hdr", long_run),
            "scan line 0 of 4: a run of 120 at pixel 0 of component 0 does not fit its width 16");
  std::string xyz = good;
  xyz.replace(xyz.find("rle_rgbe"), 8, "rle_xyze");
  EXPECT_EQ(error_of("xyz.hdr", xyz),
            "the header's 'FORMAT=32-bit_rle_xyze' is not supported; expected FORMAT=32-bit_rle_rgbe");
  EXPECT_EQ(error_of("turned.hdr", "#?RADIANCE\n\n+X 4 -Y 2\n"),
            "the resolution line '+X 4 -Y 2' is not '-Y height +X width' (or '+Y height +X width')");
  EXPECT_EQ(error_of("headless.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"),
            "the header ends before the resolution line");
  EXPECT_EQ(error_of("huge.hdr", "#?RADIANCE\n\n-Y 99999999999999999999 +X 4\n"),
            "the resolution line '-Y 99999999999999999999 +X 4' is not '-Y height +X width' (or '+Y height +X width')");
  const size_t pixels = good.find("+X 16\n") + 6;  // a header written with CR LF: the same image
  std::string crlf;
  for (char c : good.substr(0, pixels)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  write_bytes(folder.file("crlf.hdr"), crlf + good.substr(pixels));
  EXPECT_EQ(load_image(folder.file("crlf.hdr")).rgba, load_image(folder.file("good.hdr")).rgba);
}

}  // namespace
}  // namespace lg
