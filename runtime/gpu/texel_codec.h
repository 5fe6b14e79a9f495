// Converts texels between a format's bytes and float RGBA (4 floats a texel), the way the GPU
// would: channels a format lacks read as 0 (alpha as 1), sRGB decodes to linear, normalized
// formats clamp and round to nearest. Upload and readback use it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "runtime/gpu/format.h"

namespace lg {

// `rgba` holds 4 floats per texel; `bytes` holds format.bytes_per_texel per texel.
void encode_texels(const FormatInfo& format, std::span<const float> rgba, std::span<std::byte> bytes);
void decode_texels(const FormatInfo& format, std::span<const std::byte> bytes, std::span<float> rgba);

// The sRGB transfer function of one channel, clamped to [0, 1] (NaN gives 0).
float linear_to_srgb(float value);

// IEEE half precision, round to nearest even; overflow gives infinity, NaN stays NaN.
uint16_t float_to_half(float value);
float half_to_float(uint16_t bits);

}  // namespace lg
