// Image files (runtime/image): what the EXR header check refuses before OpenEXR reads a header
// that declares more bytes than the file holds, and that real files still load.
#include "runtime/image/image_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace lg {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("lumagraph-image-file-test-" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream((path / name).string(), std::ios::binary) << bytes;
    return (path / name).string();
  }
};

std::string open_error(const std::string& path) {
  try {
    ImageReader reader(path);
  } catch (const ImageFileError& e) {
    return e.what();
  }
  return "opened";
}

// The fuzzer's finding: a 200-byte file whose 'capDate' string claims 1.09 GB. OpenEXR alone
// took 10 s and 1.3 GB to refuse it, with a message that did not say why.
TEST(ImageFile, ExrAttributeLongerThanTheFileIsRefusedByName) {
  const std::string path =
      std::string(LUMAGRAPH_SOURCE_DIR "/fuzz/regressions/env_image/exr-string-attribute-claims-1gb");
  const std::string message = open_error(path);
  EXPECT_EQ(message.rfind(path + ": error: the EXR header's attribute 'capDate' (string) declares 1095909155 bytes", 0),
            0u)
      << message;
}

TEST(ImageFile, ExrWithAnAttributeSizeMadeTooLargeIsRefusedAndTheTrueOneLoads) {
  TempFolder folder;
  const std::vector<float> rgba(4 * 3 * 4, 0.5f);
  const std::string good = (folder.path / "good.exr").string();
  save_image(good, 4, 3, rgba, {.compress = false, .full_float = true});
  const ImageData image = load_image(good);
  EXPECT_EQ(image.width, 4u);
  EXPECT_EQ(image.rgba[5], 0.5f);

  // The first attribute's size follows its name and type after the 8-byte magic and version.
  std::string bytes = read_bytes(good);
  const size_t name_end = bytes.find('\0', 8), type_end = bytes.find('\0', name_end + 1);
  const std::string name = bytes.substr(8, name_end - 8);
  bytes[type_end + 4] = '\x7f';  // the size's high byte: about 2 GB
  const std::string bad = folder.write("bad.exr", bytes);
  const std::string message = open_error(bad);
  EXPECT_NE(message.find("attribute '" + name + "'"), std::string::npos) << message;
}

// Two headers the fuzzer found, whose sizes disagree with their content: OpenEXR reads channel
// lists and fixed-size values by content, then read a "size" of gigabytes out of the bytes that
// followed (seconds per file). Each is refused by the attribute it breaks.
TEST(ImageFile, ExrWhoseAttributeSizeDisagreesWithItsContentIsRefusedByName) {
  TempFolder folder;
  const std::vector<float> rgba(4 * 3 * 4, 0.5f);
  const std::string good = (folder.path / "good.exr").string();
  save_image(good, 4, 3, rgba, {.compress = false, .full_float = true});
  const std::string bytes = read_bytes(good);
  // Each attribute's size is the 4 bytes after its name and type.
  const auto with_size = [&](const std::string& name_and_type, char size) {
    std::string changed = bytes;
    const size_t at = changed.find(name_and_type);
    EXPECT_NE(at, std::string::npos) << name_and_type;
    changed[at + name_and_type.size()] = size;
    return folder.write(name_and_type.substr(0, name_and_type.find('\0')) + ".exr", changed);
  };
  const std::string channels = with_size(std::string("channels\0chlist\0", 16), 20);
  EXPECT_EQ(open_error(channels).rfind(channels + ": error: the EXR header's attribute 'channels' (chlist) does not "
                                                  "end at its declared 20 bytes",
                                       0),
            0u)
      << open_error(channels);
  const std::string compression = with_size(std::string("compression\0compression\0", 24), 2);
  EXPECT_EQ(open_error(compression)
                .rfind(compression + ": error: the EXR header's attribute 'compression' (compression) declares 2 "
                                     "bytes where its type has 1",
                       0),
            0u)
      << open_error(compression);
}

// OpenEXR sizes its line buffers from the data window when it opens a file: a 300-byte file
// declaring 2^30 x 16 pixels made it allocate and clear gigabytes before the reader's own
// limit was checked.
TEST(ImageFile, ExrWhoseDataWindowIsOverTheLimitIsRefusedBeforeOpenExrOpensIt) {
  TempFolder folder;
  const std::vector<float> rgba(4 * 3 * 4, 0.5f);
  const std::string good = (folder.path / "good.exr").string();
  save_image(good, 4, 3, rgba, {.compress = false, .full_float = true});
  std::string bytes = read_bytes(good);
  const std::string attribute("dataWindow\0box2i\0", 17);
  const size_t window = bytes.find(attribute);
  ASSERT_NE(window, std::string::npos);
  const size_t x_max = window + attribute.size() + 4 + 8;       // after the size: xMin, yMin, then xMax
  bytes.replace(x_max, 4, std::string("\xff\xff\xff\x3f", 4));  // 2^30 - 1
  const std::string bad = folder.write("wide.exr", bytes);
  EXPECT_EQ(open_error(bad).rfind(bad + ": error: the EXR header's attribute 'dataWindow' (box2i) is 1073741824x3, "
                                        "larger than the limit of 67108864 pixels",
                                  0),
            0u)
      << open_error(bad);
}

// Under the pixel limit but one line 2^24 pixels wide, ZIP-compressed (16 lines a block) with 4
// half channels: OpenEXR allocated its 2 GiB block on opening (found by fuzz/env_image_fuzzer.cpp).
TEST(ImageFile, ExrWhoseBlocksWouldTakeGigabytesIsRefusedBeforeOpenExrOpensIt) {
  TempFolder folder;
  const std::vector<float> rgba(4 * 3 * 4, 0.5f);
  const std::string good = (folder.path / "good.exr").string();
  save_image(good, 4, 3, rgba);  // ZIP, half floats
  std::string bytes = read_bytes(good);
  const std::string attribute("dataWindow\0box2i\0", 17);
  const size_t window = bytes.find(attribute);
  ASSERT_NE(window, std::string::npos);
  const size_t at = window + attribute.size() + 4;  // after the size: xMin, yMin, xMax, yMax
  bytes.replace(at, 16, std::string("\0\0\0\0\0\0\0\0\xff\xff\xff\x00\0\0\0\0", 16));  // 2^24 x 1
  const std::string bad = folder.write("wide-block.exr", bytes);
  EXPECT_EQ(open_error(bad).rfind(bad + ": error: the EXR header asks for blocks of ", 0), 0u) << open_error(bad);
  EXPECT_NE(open_error(bad).find("over the reader's limit of 64 MiB"), std::string::npos) << open_error(bad);
}

// Tiles of 2^30 x 2^30 pixels (valid sizes to OpenEXR) of four float channels: 2^64 bytes, which
// wrapped to 0 in 64 bits and passed the block limit.
TEST(ImageFile, ExrWhoseTilesOverflowSixtyFourBitsIsRefused) {
  TempFolder folder;
  std::string bytes("\x76\x2f\x31\x01\x02\x02\0\0", 8);                           // version 2, tiled
  bytes += std::string("channels\0chlist\0", 16) + std::string("\x49\0\0\0", 4);  // 4 x 18 + 1 bytes:
  for (const char* name : {"A", "B", "G", "R"})
    bytes += std::string(name) + '\0' + std::string("\x02\0\0\0\0\0\0\0\x01\0\0\0\x01\0\0\0", 16);  // FLOAT, 1 x 1
  bytes += '\0';
  bytes += std::string("tiles\0tiledesc\0", 15) + std::string("\x09\0\0\0", 4);  // 9 bytes:
  bytes += std::string("\0\0\0\x40\0\0\0\x40\0", 9);                             // 2^30 x 2^30, one level
  bytes += '\0';                                                                 // the header's end
  const std::string bad = folder.write("huge-tiles.exr", bytes);
  EXPECT_EQ(open_error(bad).rfind(bad + ": error: the EXR header asks for blocks of ", 0), 0u) << open_error(bad);
}

TEST(ImageFile, ExrWithANameLongerThanAnyExrAllowsIsRefused) {
  TempFolder folder;
  std::string bytes("\x76\x2f\x31\x01\x02\0\0\0", 8);
  bytes += std::string(300, 'n') + '\0';
  const std::string bad = folder.write("long.exr", bytes);
  EXPECT_EQ(open_error(bad).rfind(bad + ": error: the EXR header has a name longer than 255 characters", 0), 0u)
      << open_error(bad);
}

}  // namespace
}  // namespace lg
