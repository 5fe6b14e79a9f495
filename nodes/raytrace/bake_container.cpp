// Encoding and decoding the bake container (bake_container.h).
#include "nodes/raytrace/bake_container.h"

#include <bit>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "graph/diagnostics.h"
#include "graph/json_reader.h"
#include "graph/json_writer.h"

namespace lg {
namespace {

constexpr uint64_t max_header_bytes = 64u << 20;
constexpr size_t alignment = 16;

size_t aligned(size_t bytes) {
  return (bytes + alignment - 1) / alignment * alignment;
}

}  // namespace

std::string hex64(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

void set_chunk_json(JsonValue& header, uint32_t index, uint32_t count, uint64_t begin, uint64_t end) {
  JsonValue& chunk = header.set("chunk", JsonValue::object());
  chunk.set("index", uint64_t(index));
  chunk.set("count", uint64_t(count));
  chunk.set("begin", begin);
  chunk.set("end", end);
}

std::string encode_bake_container(std::string_view magic, JsonValue header,
                                  std::span<const BakeArray<const std::vector<float>>> arrays) {
  JsonValue& list = header.set("arrays", JsonValue::array());
  uint64_t offset = 0;
  for (const auto& a : arrays) {
    JsonValue entry = JsonValue::object();
    entry.set("name", a.name);
    entry.set("type", "float32");
    entry.set("components", uint64_t(a.components));
    entry.set("offset", offset);
    entry.set("bytes", uint64_t(a.values->size() * sizeof(float)));
    list.push(std::move(entry));
    offset += a.values->size() * sizeof(float);
  }
  const std::string text = write_json(header) + "\n";
  std::string out(magic);
  const uint64_t length = text.size();
  for (int b = 0; b < 8; ++b) out.push_back(char((length >> (8 * b)) & 0xff));
  out += text;
  out.resize(aligned(out.size()), '\0');
  static_assert(std::endian::native == std::endian::little, "the format's floats are little-endian");
  for (const auto& a : arrays)
    out.append(reinterpret_cast<const char*>(a.values->data()), a.values->size() * sizeof(float));
  return out;
}

void HeaderReader::fail(const std::string& message) const {
  throw BakeFileError(path_ + ": " + message);
}

const JsonValue& HeaderReader::member(const JsonValue& object, const char* key) const {
  const JsonValue* v = object.is_object() ? object.find(key) : nullptr;
  if (!v) fail(std::string("the header lacks \"") + key + "\"");
  return *v;
}

uint64_t HeaderReader::integer(const JsonValue& object, const char* key, uint64_t max) const {
  const JsonValue& v = member(object, key);
  if (!v.is_integer() || v.as_number() < 0 || v.as_number() > double(max))
    fail(std::string("header \"") + key + "\" must be an integer from 0 to " + std::to_string(max));
  return uint64_t(v.as_number());
}

double HeaderReader::number(const JsonValue& v, const char* key) const {
  if (!v.is_number()) fail(std::string("header \"") + key + "\" must be a number");
  return v.as_number();
}

const std::string& HeaderReader::string(const JsonValue& object, const char* key) const {
  const JsonValue& v = member(object, key);
  if (!v.is_string()) fail(std::string("header \"") + key + "\" must be a string");
  return v.as_string();
}

glm::dvec3 HeaderReader::vec3(const JsonValue& object, const char* key) const {
  const JsonValue& v = member(object, key);
  if (!v.is_array() || v.size() != 3) fail(std::string("header \"") + key + "\" must be an array of 3 numbers");
  return {number(v.items()[0], key), number(v.items()[1], key), number(v.items()[2], key)};
}

uint64_t HeaderReader::hex64(const JsonValue& object, const char* key) const {
  const std::string& text = string(object, key);
  char* end = nullptr;
  const uint64_t value = std::strtoull(text.c_str(), &end, 16);
  if (text.size() != 16 || *end != '\0') fail(std::string("header \"") + key + "\" must be 16 hexadecimal digits");
  return value;
}

BakeContainer read_bake_container(const std::string& path, std::string_view magic, const std::string& what) {
  const HeaderReader in(path);
  std::ifstream stream(path, std::ios::binary);
  if (!stream) in.fail("cannot open the file");
  std::ostringstream buffer;
  buffer << stream.rdbuf();
  BakeContainer file;
  file.bytes = buffer.str();
  const std::string& bytes = file.bytes;
  if (bytes.size() < 16 || std::string_view(bytes).substr(0, magic.size()) != magic)
    in.fail("not a " + what + " file (it does not start with " + std::string(magic) + ")");
  uint64_t length = 0;
  for (int b = 0; b < 8; ++b) length |= uint64_t(uint8_t(bytes[8 + b])) << (8 * b);
  if (length > max_header_bytes || 16 + length > bytes.size())
    in.fail("the header length " + std::to_string(length) + " runs past the end of the file (truncated?)");
  Diagnostics diagnostics(path);
  std::optional<JsonValue> json = read_json(std::string_view(bytes).substr(16, length), diagnostics);
  if (!json) in.fail("the header is not valid JSON: " + diagnostics.to_string());
  if (!json->is_object()) in.fail("the header is not a JSON object");
  file.header = std::move(*json);
  file.data_start = aligned(16 + length);
  return file;
}

void BakeContainer::read_arrays(const HeaderReader& in, std::span<const BakeArray<std::vector<float>>> arrays) const {
  size_t expected_size = data_start;
  for (const auto& a : arrays) expected_size += a.values->size() * sizeof(float);
  if (bytes.size() != expected_size)
    in.fail("the file has " + std::to_string(bytes.size()) + " bytes; its header describes " +
            std::to_string(expected_size) + " (truncated or damaged)");
  size_t offset = data_start;
  for (const auto& a : arrays) {
    std::memcpy(a.values->data(), bytes.data() + offset, a.values->size() * sizeof(float));
    offset += a.values->size() * sizeof(float);
  }
}

std::vector<size_t> chunk_order(const std::vector<ChunkId>& chunks, const std::vector<std::string>& paths) {
  const uint32_t count = chunks.at(0).count;
  std::map<uint32_t, size_t> by_index;
  for (size_t p = 0; p < chunks.size(); ++p) {
    if (chunks[p].count != count)
      throw BakeFileError(paths[p] + ": is a chunk of " + std::to_string(chunks[p].count) + ", " + paths[0] + " of " +
                          std::to_string(count));
    if (auto [at, fresh] = by_index.emplace(chunks[p].index, p); !fresh)
      throw BakeFileError(paths[p] + ": chunk " + std::to_string(chunks[p].index) + " is also in " + paths[at->second]);
  }
  if (by_index.size() != count) {
    std::string missing;
    for (uint32_t i = 0; i < count && missing.size() < 200; ++i)
      if (!by_index.contains(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
    throw BakeFileError("merge: chunks missing of " + std::to_string(count) + ": " + missing);
  }
  std::vector<size_t> order;
  for (const auto& [index, p] : by_index) order.push_back(p);
  return order;
}

void write_bake_bytes(const std::string& path, const std::string& bytes) {
  std::string error;
  if (!write_file_atomically(path, bytes, &error)) throw BakeFileError(path + ": " + error);
}

bool starts_with_magic(const std::string& path, std::string_view magic) {
  std::ifstream stream(path, std::ios::binary);
  std::string head(magic.size(), '\0');
  return stream.read(head.data(), std::streamsize(head.size())) && head == magic;
}

}  // namespace lg
