#include "runtime/image/exr_header_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include "runtime/image/image_file.h"

namespace lg {
namespace {

constexpr std::array<unsigned char, 4> kMagic{0x76, 0x2f, 0x31, 0x01};
constexpr size_t kMaxName = 255;  // with the long-names flag; 31 without

// A NUL-terminated name or type; nullopt when the file ends or it is longer than any EXR allows.
std::optional<std::string> read_name(std::ifstream& in) {
  std::string name;
  for (char c; in.get(c);) {
    if (c == '\0') return name;
    if (name.size() == kMaxName) return std::nullopt;
    name += c;
  }
  return std::nullopt;
}

}  // namespace

void check_exr_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff file_size = in.tellg();
  std::array<unsigned char, 8> start{};
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(start.data()), start.size()) ||
      !std::equal(kMagic.begin(), kMagic.end(), start.begin()))
    return;
  const bool multipart = start[5] & 0x10;  // bit 12 of the version field
  // Attributes (name, type, int32 size, value) up to an empty name; a multi-part file has a
  // header per part, and one more empty name after the last.
  bool header_ended = false;
  for (;;) {
    const std::optional<std::string> name = read_name(in);
    if (!name) return;
    if (name->empty()) {
      if (!multipart || header_ended) return;
      header_ended = true;
      continue;
    }
    header_ended = false;
    const std::optional<std::string> type = read_name(in);
    std::array<unsigned char, 4> bytes{};
    if (!type || !in.read(reinterpret_cast<char*>(bytes.data()), bytes.size())) return;
    const int32_t size =
        int32_t(uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 | uint32_t(bytes[3]) << 24);
    const std::streamoff at = in.tellg();
    if (size < 0 || at + size > file_size)
      throw ImageFileError(path + ": error: the EXR header's attribute '" + *name + "' (" + *type + ") declares " +
                           std::to_string(size) + " bytes at byte " + std::to_string(at) + " of a " +
                           std::to_string(file_size) + "-byte file");
    in.seekg(size, std::ios::cur);
  }
}

}  // namespace lg
