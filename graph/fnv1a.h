// FNV-1a, 64 bits: a fast, stable hash of bytes for cache keys, file names and checksums that
// must come out the same in every process and build (std::hash promises neither).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace lg {

constexpr uint64_t fnv1a_basis = 0xcbf29ce484222325ull;

// Continues `hash` over `bytes`; start from fnv1a_basis.
constexpr uint64_t fnv1a(std::span<const std::byte> bytes, uint64_t hash = fnv1a_basis) {
  for (std::byte b : bytes) hash = (hash ^ static_cast<uint8_t>(b)) * 0x100000001b3ull;
  return hash;
}

inline uint64_t fnv1a(std::string_view text, uint64_t hash = fnv1a_basis) {
  return fnv1a(std::as_bytes(std::span(text.data(), text.size())), hash);
}

// The bytes of `size` bytes at `data` (a value's representation, padding included).
inline uint64_t fnv1a(const void* data, size_t size, uint64_t hash) {
  return fnv1a(std::span(static_cast<const std::byte*>(data), size), hash);
}

}  // namespace lg
