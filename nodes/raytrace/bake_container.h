// The container every CPU bake file shares (.lgbake, .lgprobes; docs/bake-format.md): an 8-byte
// magic, the header's length (uint64, little-endian), the header (UTF-8 JSON and a newline), zero
// padding to a multiple of 16 bytes, then float32 arrays (little-endian) in the order of the
// header's "arrays" list. Also the typed reading of header fields, with errors naming the file.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "graph/json_value.h"

namespace lg {

// A file that cannot be read, is not a bake, is damaged, or does not fit with the others.
// The message starts with the file's path.
class BakeFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One array of a file: `components` floats a point. Values is std::vector<float> to read into,
// const std::vector<float> to write from.
template <class Values>
struct BakeArray {
  const char* name;
  uint32_t components;
  Values* values;
};

// The file's bytes: `header` gains the "arrays" list describing `arrays`.
std::string encode_bake_container(std::string_view magic, JsonValue header,
                                  std::span<const BakeArray<const std::vector<float>>> arrays);

// Adds the "chunk" object every bake header carries: which of `count` chunks this file is, and
// the range of points it holds.
void set_chunk_json(JsonValue& header, uint32_t index, uint32_t count, uint64_t begin, uint64_t end);

// Reading: typed header fields with errors that name the file and the key.
class HeaderReader {
 public:
  explicit HeaderReader(const std::string& path) : path_(path) {}
  [[noreturn]] void fail(const std::string& message) const;
  const JsonValue& member(const JsonValue& object, const char* key) const;
  uint64_t integer(const JsonValue& object, const char* key, uint64_t max = uint64_t(1) << 53) const;
  double number(const JsonValue& v, const char* key) const;
  const std::string& string(const JsonValue& object, const char* key) const;
  glm::dvec3 vec3(const JsonValue& object, const char* key) const;
  // 16 hexadecimal digits (a hash).
  uint64_t hex64(const JsonValue& object, const char* key) const;

 private:
  const std::string& path_;
};

// A container read from disk: its header and where its arrays start.
struct BakeContainer {
  JsonValue header;
  std::string bytes;
  size_t data_start = 0;

  // Fills `arrays` (each already sized from the header) from the data; fails, naming the file,
  // unless the file holds exactly those arrays.
  void read_arrays(const HeaderReader& in, std::span<const BakeArray<std::vector<float>>> arrays) const;
};

// Reads the file's header; `what` names the kind of file in errors ("bake", "probe bake").
// Throws BakeFileError naming `path`.
BakeContainer read_bake_container(const std::string& path, std::string_view magic, const std::string& what);

// Which chunk of how many each part of a bake is.
struct ChunkId {
  uint32_t index = 0, count = 1;
};

// The parts (one per path) in chunk order; throws BakeFileError naming a part that is a chunk of
// another count or repeats a chunk, or listing the chunks missing.
std::vector<size_t> chunk_order(const std::vector<ChunkId>& chunks, const std::vector<std::string>& paths);

// Writes `bytes` to `path` atomically; throws BakeFileError naming the file.
void write_bake_bytes(const std::string& path, const std::string& bytes);

// Whether the file at `path` starts with `magic` (false when it cannot be read).
bool starts_with_magic(const std::string& path, std::string_view magic);

std::string hex64(uint64_t v);

}  // namespace lg
