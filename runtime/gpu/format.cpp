#include "runtime/gpu/format.h"

#include <string>

#include "runtime/gpu/gpu_error.h"

namespace lg {

std::span<const FormatInfo> known_formats() {
  using E = TexelEncoding;
  static const FormatInfo table[] = {
      {"r8", VK_FORMAT_R8_UNORM, 1, 1, E::unorm8},
      {"rg8", VK_FORMAT_R8G8_UNORM, 2, 2, E::unorm8},
      {"rgba8", VK_FORMAT_R8G8B8A8_UNORM, 4, 4, E::unorm8},
      {"rgba8_srgb", VK_FORMAT_R8G8B8A8_SRGB, 4, 4, E::srgb8},
      {"rgba8_snorm", VK_FORMAT_R8G8B8A8_SNORM, 4, 4, E::snorm8},
      {"r16f", VK_FORMAT_R16_SFLOAT, 1, 2, E::float16},
      {"rg16f", VK_FORMAT_R16G16_SFLOAT, 2, 4, E::float16},
      {"rgba16f", VK_FORMAT_R16G16B16A16_SFLOAT, 4, 8, E::float16},
      {"r32f", VK_FORMAT_R32_SFLOAT, 1, 4, E::float32},
      {"rg32f", VK_FORMAT_R32G32_SFLOAT, 2, 8, E::float32},
      {"rgba32f", VK_FORMAT_R32G32B32A32_SFLOAT, 4, 16, E::float32},
      {"rgb10a2", VK_FORMAT_A2B10G10R10_UNORM_PACK32, 4, 4, E::unorm10_10_10_2},
      {"d32f", VK_FORMAT_D32_SFLOAT, 1, 4, E::float32, true},
  };
  return table;
}

const FormatInfo& format_info(std::string_view name) {
  for (const FormatInfo& f : known_formats())
    if (f.name == name) return f;
  std::string known;
  for (const FormatInfo& f : known_formats()) known += (known.empty() ? "" : ", ") + std::string(f.name);
  throw GpuError("unknown texel format '" + std::string(name) + "'; known formats: " + known);
}

const FormatInfo& format_info(VkFormat format) {
  for (const FormatInfo& f : known_formats())
    if (f.format == format) return f;
  throw GpuError("VkFormat " + std::to_string(static_cast<int>(format)) + " is not one Lumagraph knows");
}

}  // namespace lg
