// Radiance RGBE (.hdr): a text header ("#?" program line, variables such as
// FORMAT=32-bit_rle_rgbe, an empty line, then the resolution "-Y height +X width"), then per
// scan line either 4 bytes a pixel (red, green and blue mantissas sharing one exponent) or, for
// widths 8 to 32767, the "new" run-length encoding: 2, 2, width's two bytes, then each of the 4
// components as runs (a count above 128: that many minus 128 of the next byte; otherwise that
// many literal bytes). A value is mantissa * 2^(exponent - 136), 0 where the exponent is 0.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "runtime/image/image_file.h"
#include "runtime/image/image_formats.h"

namespace lg {
namespace {

constexpr size_t kMaxHeaderLine = 4096;
constexpr int kMaxHeaderLines = 1024;

struct Resolution {
  uint32_t width, height;
  bool bottom_up;  // "+Y": the first stored scan line is the bottom one
};

// "-Y height +X width" or "+Y height +X width", sizes 1 to 2^31 - 1; anything else: nullopt.
std::optional<Resolution> parse_resolution(const std::string& line) {
  std::istringstream in(line);
  std::string y, h, x, w, rest;
  if (!(in >> y >> h >> x >> w) || (in >> rest) || (y != "-Y" && y != "+Y") || x != "+X") return std::nullopt;
  const auto size = [](const std::string& digits) -> uint64_t {
    if (digits.empty() || digits.size() > 10 || digits.find_first_not_of("0123456789") != std::string::npos) return 0;
    return std::stoull(digits);
  };
  const uint64_t height = size(h), width = size(w);
  if (height == 0 || width == 0 || height > 0x7fffffff || width > 0x7fffffff) return std::nullopt;
  return Resolution{uint32_t(width), uint32_t(height), y == "+Y"};
}

class RgbeReader final : public FormatReader {
 public:
  explicit RgbeReader(const std::string& path) : path_(path), file_(path, "rb") {
    if (!file_.handle) throw ImageFileError(path + ": error: cannot open the image");
    std::string line = read_line();
    if (line.rfind("#?", 0) != 0) fail("not a Radiance HDR file (it does not start with '#?')");
    for (int n = 0;; ++n) {
      if (n == kMaxHeaderLines) fail("the header has more than " + std::to_string(kMaxHeaderLines) + " lines");
      line = read_line();
      if (line.empty()) break;
      if (line.rfind("FORMAT=", 0) == 0 && line != "FORMAT=32-bit_rle_rgbe")
        fail("the header's '" + line + "' is not supported; expected FORMAT=32-bit_rle_rgbe");
    }
    line = read_line();
    const std::optional<Resolution> size = parse_resolution(line);
    if (!size) fail("the resolution line '" + line + "' is not '-Y height +X width' (or '+Y height +X width')");
    width = size->width, height = size->height;
    bottom_up_ = size->bottom_up;
  }

  void read_rgba(std::span<float> rgba) override {
    std::array<float, 256> scale;  // of each exponent: one table, not a ldexp a pixel
    for (int e = 0; e < 256; ++e) scale[e] = e == 0 ? 0.0f : std::ldexp(1.0f, e - 136);
    std::vector<uint8_t> scan(size_t(width) * 4);
    for (uint32_t y = 0; y < height; ++y) {
      read_scan_line(scan, y);
      float* out = rgba.data() + size_t(bottom_up_ ? height - 1 - y : y) * width * 4;
      for (uint32_t x = 0; x < width; ++x) {
        const uint8_t* p = &scan[4 * size_t(x)];
        for (int c = 0; c < 3; ++c) out[4 * x + c] = float(p[c]) * scale[p[3]];
        out[4 * x + 3] = 1.0f;
      }
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw ImageFileError(path_ + ": error: " + why); }
  // Where a scan line failed, in the file's order (the first stored is line 0).
  std::string where(uint32_t line) const {
    return "scan line " + std::to_string(line) + " of " + std::to_string(height);
  }
  [[noreturn]] void truncated(uint32_t line) const {
    fail("the pixels cannot be read (truncated or corrupt?): the file ends inside " + where(line));
  }

  std::string read_line() {
    std::string line;
    for (int c; (c = next_byte()) != '\n';) {
      if (c == EOF) fail("the header ends before the resolution line");
      if (line.size() == kMaxHeaderLine) fail("a header line is longer than " + std::to_string(kMaxHeaderLine));
      line += char(c);
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a header written with CR LF
    return line;
  }

  // The next byte of the file, EOF at its end; the file is read a block at a time (a locked fgetc a
  // byte made a 4096 x 2048 probe's load 195 ms rather than 139).
  int next_byte() {
    if (at_ == end_ && !refill()) return EOF;
    return block_[at_++];
  }
  bool refill() {
    at_ = 0;
    end_ = std::fread(block_.data(), 1, block_.size(), file_.handle);
    return end_ > 0;
  }
  uint8_t byte(uint32_t line) {
    const int c = next_byte();
    if (c == EOF) truncated(line);
    return uint8_t(c);
  }
  // `n` bytes, `stride` apart from `out`.
  void bytes(uint32_t line, uint8_t* out, size_t n, size_t stride) {
    while (n > 0) {
      if (at_ == end_ && !refill()) truncated(line);
      const size_t take = std::min(n, end_ - at_);
      for (size_t i = 0; i < take; ++i) out[i * stride] = block_[at_ + i];
      at_ += take, out += take * stride, n -= take;
    }
  }

  void read_scan_line(std::vector<uint8_t>& scan, uint32_t line) {
    uint8_t start[4];
    bytes(line, start, 4, 1);
    const bool encoded = width >= 8 && width <= 0x7fff && start[0] == 2 && start[1] == 2 && !(start[2] & 0x80);
    if (!encoded) {
      std::memcpy(scan.data(), start, 4);
      bytes(line, scan.data() + 4, scan.size() - 4, 1);
      return;
    }
    if (((uint32_t(start[2]) << 8) | start[3]) != width)
      fail(where(line) + ": its run-length header gives width " + std::to_string((start[2] << 8) | start[3]) +
           ", not the image's " + std::to_string(width));
    for (int c = 0; c < 4; ++c)
      for (uint32_t x = 0; x < width;) {
        const uint32_t count = byte(line);
        const bool run = count > 128;
        const uint32_t n = run ? count - 128 : count;
        if (n == 0 || x + n > width)
          fail(where(line) + ": a run of " + std::to_string(n) + " at pixel " + std::to_string(x) + " of component " +
               std::to_string(c) + " does not fit its width " + std::to_string(width));
        if (run) {
          const uint8_t value = byte(line);
          for (uint32_t i = 0; i < n; ++i) scan[4 * size_t(x + i) + c] = value;
        } else {
          bytes(line, &scan[4 * size_t(x) + c], n, 4);
        }
        x += n;
      }
  }

  std::string path_;
  CFile file_;
  std::vector<uint8_t> block_ = std::vector<uint8_t>(size_t(1) << 16);
  size_t at_ = 0, end_ = 0;  // the block's unread bytes
  bool bottom_up_ = false;
};

// The shared exponent and mantissas of an RGB value (negative and non-finite components as 0).
void encode(const float* rgb, uint8_t* out) {
  float c[3];
  for (int i = 0; i < 3; ++i) c[i] = std::isfinite(rgb[i]) && rgb[i] > 0.0f ? rgb[i] : 0.0f;
  const float largest = std::max({c[0], c[1], c[2]});
  if (largest < 1e-32f) {
    std::memset(out, 0, 4);
    return;
  }
  int exponent = 0;
  std::frexp(largest, &exponent);
  exponent = std::min(exponent, 127);  // beyond RGBE's range: its largest mantissas
  const float scale = std::ldexp(1.0f, 8 - exponent);
  for (int i = 0; i < 3; ++i) out[i] = uint8_t(std::min(c[i] * scale, 255.0f));
  out[3] = uint8_t(exponent + 128);
}

}  // namespace

std::unique_ptr<FormatReader> open_rgbe(const std::string& path) {
  return std::make_unique<RgbeReader>(path);
}

void write_rgbe(const std::string& path, uint32_t width, uint32_t height, std::span<const float> rgba) {
  CFile file(path, "wb");
  if (!file.handle) throw std::runtime_error("cannot create the file");
  bool ok = std::fprintf(file.handle, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %u +X %u\n", height, width) > 0;
  // Run-length encoded where the format allows it (so no flat scan line can be mistaken for an
  // encoded one's start), as literal runs of at most 128 bytes.
  const bool encoded = width >= 8 && width <= 0x7fff;
  std::vector<uint8_t> pixels(size_t(width) * 4), line;
  for (uint32_t y = 0; ok && y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) encode(&rgba[(size_t(y) * width + x) * 4], &pixels[4 * size_t(x)]);
    line.clear();
    if (!encoded) {
      line = pixels;
    } else {
      line = {2, 2, uint8_t(width >> 8), uint8_t(width & 0xff)};
      for (int c = 0; c < 4; ++c)
        for (uint32_t x = 0; x < width; x += 128) {
          const uint32_t n = std::min(width - x, 128u);
          line.push_back(uint8_t(n));
          for (uint32_t i = 0; i < n; ++i) line.push_back(pixels[4 * size_t(x + i) + c]);
        }
    }
    ok = std::fwrite(line.data(), 1, line.size(), file.handle) == line.size();
  }
  if (!ok || std::fflush(file.handle) != 0) throw std::runtime_error("the disk refused the bytes");
}

}  // namespace lg
