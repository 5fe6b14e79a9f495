#include "runtime/gpu/texel_codec.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "runtime/gpu/gpu_error.h"

namespace lg {
namespace {

// Clamps to [lo, hi]; NaN becomes 0, as Vulkan converts it for normalized formats.
float saturate(float v, float lo, float hi) { return v >= lo ? (v <= hi ? v : hi) : (v < lo ? lo : 0.0f); }

uint32_t to_unorm(float v, uint32_t max) { return static_cast<uint32_t>(std::lround(saturate(v, 0, 1) * max)); }

float srgb_to_linear(float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); }

void check_sizes(const FormatInfo& format, size_t floats, size_t bytes) {
  if (floats % 4 != 0 || floats / 4 * format.bytes_per_texel != bytes)
    throw GpuError("texel conversion for " + std::string(format.name) + ": " + std::to_string(floats) +
                   " floats do not match " + std::to_string(bytes) + " bytes");
}

}  // namespace

float linear_to_srgb(float v) {
  v = saturate(v, 0, 1);
  return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

uint16_t float_to_half(float value) {
  const uint32_t x = std::bit_cast<uint32_t>(value);
  const uint16_t sign = static_cast<uint16_t>(x >> 16 & 0x8000);
  const uint32_t exponent = x >> 23 & 0xff;
  uint32_t mantissa = x & 0x7fffff;
  if (exponent == 0xff) return sign | 0x7c00 | (mantissa ? 0x200 | mantissa >> 13 : 0);  // NaN stays quiet NaN
  const int e = static_cast<int>(exponent) - 127 + 15;
  if (e >= 31) return sign | 0x7c00;
  if (e <= 0) {  // a half subnormal, or zero when below half the smallest one
    if (e < -10) return sign;
    mantissa |= 0x800000;
    const int shift = 14 - e;
    uint32_t half = mantissa >> shift;
    const uint32_t rest = mantissa & ((1u << shift) - 1), halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (half & 1))) ++half;
    return static_cast<uint16_t>(sign | half);
  }
  uint32_t half = static_cast<uint32_t>(e) << 10 | mantissa >> 13;
  const uint32_t rest = mantissa & 0x1fff;
  if (rest > 0x1000 || (rest == 0x1000 && (half & 1))) ++half;  // a carry may reach infinity, as it should
  return static_cast<uint16_t>(sign | half);
}

float half_to_float(uint16_t bits) {
  const uint32_t sign = static_cast<uint32_t>(bits & 0x8000) << 16;
  const uint32_t exponent = bits >> 10 & 0x1f, mantissa = bits & 0x3ff;
  if (exponent == 0) {
    const float v = std::ldexp(static_cast<float>(mantissa), -24);
    return sign ? -v : v;
  }
  if (exponent == 31) return std::bit_cast<float>(sign | 0x7f800000 | mantissa << 13);
  return std::bit_cast<float>(sign | (exponent + 112) << 23 | mantissa << 13);
}

void encode_texels(const FormatInfo& format, std::span<const float> rgba, std::span<std::byte> bytes) {
  check_sizes(format, rgba.size(), bytes.size());
  const size_t texels = rgba.size() / 4;
  for (size_t t = 0; t < texels; ++t) {
    const float* in = &rgba[t * 4];
    std::byte* out = &bytes[t * format.bytes_per_texel];
    for (uint32_t c = 0; c < format.channels; ++c) {
      switch (format.encoding) {
        case TexelEncoding::unorm8: out[c] = static_cast<std::byte>(to_unorm(in[c], 255)); break;
        case TexelEncoding::snorm8:
          out[c] = static_cast<std::byte>(static_cast<int8_t>(std::lround(saturate(in[c], -1, 1) * 127)));
          break;
        case TexelEncoding::srgb8:
          out[c] = static_cast<std::byte>(to_unorm(c < 3 ? linear_to_srgb(in[c]) : in[c], 255));
          break;
        case TexelEncoding::float16: {
          const uint16_t h = float_to_half(in[c]);
          std::memcpy(out + 2 * c, &h, 2);
          break;
        }
        case TexelEncoding::float32: std::memcpy(out + 4 * c, &in[c], 4); break;
        case TexelEncoding::unorm10_10_10_2: {
          if (c > 0) break;  // all four channels go into one word
          const uint32_t word = to_unorm(in[0], 1023) | to_unorm(in[1], 1023) << 10 | to_unorm(in[2], 1023) << 20 |
                                to_unorm(in[3], 3) << 30;
          std::memcpy(out, &word, 4);
          break;
        }
      }
    }
  }
}

void decode_texels(const FormatInfo& format, std::span<const std::byte> bytes, std::span<float> rgba) {
  check_sizes(format, rgba.size(), bytes.size());
  const size_t texels = rgba.size() / 4;
  for (size_t t = 0; t < texels; ++t) {
    const std::byte* in = &bytes[t * format.bytes_per_texel];
    float* out = &rgba[t * 4];
    out[0] = out[1] = out[2] = 0;
    out[3] = 1;
    for (uint32_t c = 0; c < format.channels; ++c) {
      switch (format.encoding) {
        case TexelEncoding::unorm8: out[c] = std::to_integer<uint8_t>(in[c]) / 255.0f; break;
        case TexelEncoding::snorm8:
          out[c] = std::max(static_cast<int8_t>(std::to_integer<uint8_t>(in[c])) / 127.0f, -1.0f);
          break;
        case TexelEncoding::srgb8: {
          const float v = std::to_integer<uint8_t>(in[c]) / 255.0f;
          out[c] = c < 3 ? srgb_to_linear(v) : v;
          break;
        }
        case TexelEncoding::float16: {
          uint16_t h;
          std::memcpy(&h, in + 2 * c, 2);
          out[c] = half_to_float(h);
          break;
        }
        case TexelEncoding::float32: std::memcpy(&out[c], in + 4 * c, 4); break;
        case TexelEncoding::unorm10_10_10_2: {
          uint32_t word;
          std::memcpy(&word, in, 4);
          const uint32_t shift = 10 * c, max = c < 3 ? 1023 : 3;
          out[c] = static_cast<float>(word >> shift & max) / max;
          break;
        }
      }
    }
  }
}

}  // namespace lg
