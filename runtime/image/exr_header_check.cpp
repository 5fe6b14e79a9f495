#include "runtime/image/exr_header_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "runtime/image/image_file.h"

namespace lg {
namespace {

constexpr std::array<unsigned char, 4> kMagic{0x76, 0x2f, 0x31, 0x01};
constexpr size_t kMaxName = 255;  // with the long-names flag; 31 without
// OpenEXR allocates (and under AddressSanitizer clears) a block of scan lines, or a tile, of every
// channel when it opens a file. The largest a valid environment needs: 16384 pixels wide, RGBA
// float, in DWAB's 256-line blocks, 64 MiB. A 134 MB block of one 16.7-Mpixel line took the
// fuzzer 1.5 s a file.
constexpr uint64_t kMaxBlockBytes = uint64_t(64) << 20;

// The value sizes of the standard attribute types whose size is fixed. OpenEXR reads these, and
// channel lists, by their content and not by the size the header declares, so a wrong size
// made it read the next attribute from another place than this walk did.
int32_t fixed_size(const std::string& type) {
  static const std::map<std::string, int32_t> sizes{{"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
                                                    {"compression", 1}, {"double", 8},   {"envmap", 1},
                                                    {"float", 4},       {"int", 4},      {"keycode", 28},
                                                    {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
                                                    {"m44f", 64},       {"m44d", 128},   {"rational", 8},
                                                    {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
                                                    {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
                                                    {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? -1 : it->second;
}

// A NUL-terminated name or type; nullopt when `in` runs out.
// Throws past kMaxName, which no EXR allows.
std::optional<std::string> read_name(std::istream& in, const std::string& path) {
  std::string name;
  for (char c; in.get(c);) {
    if (c == '\0') return name;
    if (name.size() == kMaxName)
      throw ImageFileError(path + ": error: the EXR header has a name longer than " + std::to_string(kMaxName) +
                           " characters ('" + name.substr(0, 16) + "...')");
    name += c;
  }
  return std::nullopt;
}

int32_t int32_at(const unsigned char* bytes) {
  return int32_t(uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24);
}

// A channel list: (name, pixel type int32, 12 more bytes) per channel, then an empty name,
// filling the value exactly. The bytes a pixel of all its channels takes, or nullopt when it does
// not fill the value.
std::optional<uint64_t> channel_list_pixel_bytes(const std::string& value, const std::string& path) {
  std::istringstream in(value);
  uint64_t bytes = 0;
  for (;;) {
    const std::optional<std::string> name = read_name(in, path);
    if (!name) return std::nullopt;
    if (name->empty()) return in.tellg() == std::streamoff(value.size()) ? std::optional(bytes) : std::nullopt;
    std::array<unsigned char, 16> channel{};
    if (!in.read(reinterpret_cast<char*>(channel.data()), channel.size())) return std::nullopt;
    bytes += int32_at(channel.data()) == 1 ? 2 : 4;  // HALF; UINT and FLOAT (others OpenEXR refuses)
  }
}

// Scan lines OpenEXR decodes at once, by compression (its enum's order); 1 for the unknown.
uint64_t lines_per_block(int compression) {
  constexpr std::array<uint64_t, 10> lines{1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < int(lines.size()) ? lines[size_t(compression)] : 1;
}

// a x b x c, or the largest uint64_t where that overflows: tiles of 2^30 x 2^30 16-byte pixels
// must not wrap to 0 bytes and pass the limit.
uint64_t saturating_product(uint64_t a, uint64_t b, uint64_t c) {
  uint64_t ab = 0, abc = 0;
  if (__builtin_mul_overflow(a, b, &ab) || __builtin_mul_overflow(ab, c, &abc)) return UINT64_MAX;
  return abc;
}

// What OpenEXR sizes its buffers from, gathered over one part's header.
struct BufferFacts {
  int64_t width = 0;                 // of the data window
  int compression = 3;               // the byte of 'compression'; without one, OpenEXR's default (ZIP)
  uint64_t pixel_bytes = 0;          // of every channel
  uint64_t tile_x = 0, tile_y = 0;   // 'tiles', where the file is tiled
};

}  // namespace

void check_exr_header(const std::string& path, uint64_t max_pixels) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff file_size = in.tellg();
  std::array<unsigned char, 8> start{};
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(start.data()), start.size()) ||
      !std::equal(kMagic.begin(), kMagic.end(), start.begin()))
    return;
  const bool multipart = start[5] & 0x10;  // bit 12 of the version field
  const auto refuse = [&](const std::string& name, const std::string& type, const std::string& what) {
    throw ImageFileError(path + ": error: the EXR header's attribute '" + name + "' (" + type + ") " + what);
  };
  // Checked where a part's header ends, when every attribute it sizes buffers from is known.
  BufferFacts facts;
  const auto check_blocks = [&] {
    const uint64_t block = facts.tile_x > 0 ? saturating_product(facts.tile_x, facts.tile_y, facts.pixel_bytes)
                                            : saturating_product(uint64_t(std::max<int64_t>(facts.width, 0)),
                                                                 lines_per_block(facts.compression), facts.pixel_bytes);
    if (block > kMaxBlockBytes)
      throw ImageFileError(path + ": error: the EXR header asks for blocks of " + std::to_string(block >> 20) +
                           " MiB (" + (facts.tile_x > 0 ? "its tiles" : "its data window's width") + " times " +
                           std::to_string(facts.pixel_bytes) + " bytes a pixel" +
                           (facts.tile_x > 0 ? "" : " times the compression's lines a block") +
                           "), over the reader's limit of " + std::to_string(kMaxBlockBytes >> 20) + " MiB");
    facts = {};
  };
  // Attributes (name, type, int32 size, value) up to an empty name; a multi-part file has a
  // header per part, and one more empty name after the last.
  bool header_ended = false;
  for (;;) {
    const std::optional<std::string> name = read_name(in, path);
    if (!name) return;
    if (name->empty()) {
      if (!header_ended) check_blocks();
      if (!multipart || header_ended) return;
      header_ended = true;
      continue;
    }
    header_ended = false;
    const std::optional<std::string> type = read_name(in, path);
    std::array<unsigned char, 4> bytes{};
    if (!type || !in.read(reinterpret_cast<char*>(bytes.data()), bytes.size())) return;
    const int32_t size = int32_at(bytes.data());
    const std::streamoff at = in.tellg();
    if (size < 0 || at + size > file_size)
      refuse(*name, *type,
             "declares " + std::to_string(size) + " bytes at byte " + std::to_string(at) + " of a " +
                 std::to_string(file_size) + "-byte file");
    if (const int32_t fixed = fixed_size(*type); fixed >= 0 && size != fixed)
      refuse(*name, *type, "declares " + std::to_string(size) + " bytes where its type has " + std::to_string(fixed));
    if (*name == "dataWindow" && *type == "box2i") {
      // OpenEXR sizes its line buffers from the data window when it opens the file.
      std::array<unsigned char, 16> box{};
      in.read(reinterpret_cast<char*>(box.data()), box.size());
      const auto at_int = [&](size_t i) { return int64_t(int32_at(&box[i])); };
      const int64_t width = at_int(8) - at_int(0) + 1, height = at_int(12) - at_int(4) + 1;
      facts.width = width;
      // OpenEXR refuses an inverted window too, but only after sizing its work from it.
      if (width <= 0 || height <= 0)
        refuse(*name, *type,
               "is inverted (x " + std::to_string(at_int(0)) + " to " + std::to_string(at_int(8)) + ", y " +
                   std::to_string(at_int(4)) + " to " + std::to_string(at_int(12)) + ")");
      if (uint64_t(width) * uint64_t(height) > max_pixels)
        refuse(*name, *type,
               "is " + std::to_string(width) + "x" + std::to_string(height) + ", larger than the limit of " +
                   std::to_string(max_pixels) + " pixels");
    } else if (*type == "chlist") {
      std::string value(static_cast<size_t>(size), '\0');
      in.read(value.data(), size);
      const std::optional<uint64_t> pixel_bytes = channel_list_pixel_bytes(value, path);
      if (!pixel_bytes) refuse(*name, *type, "does not end at its declared " + std::to_string(size) + " bytes");
      if (*name == "channels") facts.pixel_bytes = *pixel_bytes;
    } else if (*name == "compression" && *type == "compression") {
      facts.compression = in.get();
    } else if (*name == "tiles" && *type == "tiledesc") {
      std::array<unsigned char, 9> tiles{};
      in.read(reinterpret_cast<char*>(tiles.data()), tiles.size());
      facts.tile_x = uint32_t(int32_at(&tiles[0])), facts.tile_y = uint32_t(int32_at(&tiles[4]));
    } else {
      in.seekg(size, std::ios::cur);
    }
  }
}

}  // namespace lg
