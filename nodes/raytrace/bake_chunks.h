// How every CPU bake splits into chunks: a contiguous range of its points (vertices, texels,
// volume points, probes) each, so that chunks bake alone on any machine and merge bit-exactly.
#pragma once

#include <cstdint>

namespace lg {

struct PointRange {
  uint64_t begin = 0, end = 0;
  uint64_t size() const { return end - begin; }
};

// A bake splits into at most this many chunks.
inline constexpr uint32_t max_bake_chunks = 1000000;

// Chunk `index` of `count` (index < count <= max_bake_chunks, points < 2^32):
// [points * index / count, points * (index + 1) / count).
inline PointRange chunk_range(uint64_t points, uint32_t index, uint32_t count) {
  // points * index fits in 64 bits: points is below 2^32 and index below 2^20.
  return {points * index / count, points * (uint64_t(index) + 1) / count};
}

}  // namespace lg
