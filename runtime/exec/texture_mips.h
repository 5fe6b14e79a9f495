// A texture's mip chain built on the host: each level a box filter of the one above over the
// texels it covers (odd sizes included), in linear values, so that sRGB colour is averaged as
// light and not as encoded bytes.
#pragma once

#include <cstdint>
#include <vector>

namespace lg {

// Levels down to 1x1 of a width x height float RGBA image (4 floats a texel, rows in order):
// floor(log2(max(width, height))) + 1 of them, the first a copy of `rgba`.
std::vector<std::vector<float>> mip_chain(const std::vector<float>& rgba, uint32_t width, uint32_t height);

// How many levels mip_chain() makes for that size.
uint32_t mip_count(uint32_t width, uint32_t height);

}  // namespace lg
