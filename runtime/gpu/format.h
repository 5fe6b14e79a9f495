// The texel formats of plans and port types ("rgba16f", "rgba8_srgb", "d32f", ...) and their
// Vulkan formats, with the facts upload and readback need: bytes per texel, channels, encoding.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

namespace lg {

enum class TexelEncoding : uint8_t {
  unorm8,
  snorm8,
  srgb8,     // 8-bit sRGB colour, linear alpha
  float16,
  float32,
  unorm10_10_10_2,  // A2B10G10R10: r in the low bits
};

struct FormatInfo {
  std::string_view name;  // as in plans: "rgba16f"
  VkFormat format;
  uint32_t channels;      // 1 to 4
  uint32_t bytes_per_texel;
  TexelEncoding encoding;
  bool depth = false;
};

// Every format Lumagraph knows, in a fixed order.
std::span<const FormatInfo> known_formats();

// Throws GpuError naming the format and listing the known ones when it is not known.
const FormatInfo& format_info(std::string_view name);
const FormatInfo& format_info(VkFormat format);
inline VkFormat vk_format(std::string_view name) { return format_info(name).format; }

}  // namespace lg
