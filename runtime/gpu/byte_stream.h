// Bytes in and out of the cache files Lumagraph keeps on disk (the pipeline cache, static
// results): values in host byte order, since those files never leave the machine (their names
// and headers name the device). The reader checks what is left, so a truncated file is a
// refusal, never a read past its end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

namespace lg {

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    out_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_bytes(const void* data, size_t size) { out_.append(static_cast<const char*>(data), size); }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
  size_t left() const { return bytes_.size() - at_; }
  // Callers check left() first: reading past the end is a programming error.
  template <typename T>
  T get() {
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string_view get_bytes(size_t size) {
    std::string_view out = bytes_.substr(at_, size);
    at_ += out.size();
    return out;
  }

 private:
  std::string_view bytes_;
  size_t at_ = 0;
};

inline std::span<const std::byte> as_byte_span(std::string_view text) {
  return {reinterpret_cast<const std::byte*>(text.data()), text.size()};
}

// `value` in `digits` lower-case hex digits, zero-padded: for file names and messages.
inline std::string hex_digits(uint64_t value, int digits) {
  char text[17];
  std::snprintf(text, sizeof text, "%0*llx", digits, static_cast<unsigned long long>(value));
  return text;
}

}  // namespace lg
