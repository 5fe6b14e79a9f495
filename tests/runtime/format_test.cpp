// Texel formats: every format a port type names maps to Vulkan, unknown names are a clear
// error, and texel conversion round-trips (half floats, sRGB, snorm, packed 10-bit).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "graph/port_type.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/texel_codec.h"

namespace lg::test {
namespace {

TEST(Format, EveryPortTypeFormatIsKnown) {
  int images = 0;
  for (const PortType& type : all_port_types())
    for (const PortComponent& c : type.components()) {
      if (c.format == "buffer") continue;
      const FormatInfo& info = format_info(c.format);
      EXPECT_EQ(info.bytes_per_texel, c.bytes_per_texel) << c.format;
      EXPECT_EQ(info.depth, c.depth) << c.format;
      ++images;
    }
  EXPECT_GT(images, 10);
}

TEST(Format, NamesMapToVulkanFormats) {
  EXPECT_EQ(vk_format("rgba16f"), VK_FORMAT_R16G16B16A16_SFLOAT);
  EXPECT_EQ(vk_format("rgba8"), VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_EQ(vk_format("rgba8_srgb"), VK_FORMAT_R8G8B8A8_SRGB);
  EXPECT_EQ(vk_format("rgba8_snorm"), VK_FORMAT_R8G8B8A8_SNORM);
  EXPECT_EQ(vk_format("r32f"), VK_FORMAT_R32_SFLOAT);
  EXPECT_EQ(vk_format("d32f"), VK_FORMAT_D32_SFLOAT);
  EXPECT_EQ(vk_format("rgb10a2"), VK_FORMAT_A2B10G10R10_UNORM_PACK32);
  EXPECT_EQ(vk_format("rg8"), VK_FORMAT_R8G8_UNORM);
  EXPECT_EQ(vk_format("rg16f"), VK_FORMAT_R16G16_SFLOAT);
  EXPECT_EQ(vk_format("r8"), VK_FORMAT_R8_UNORM);
  for (const FormatInfo& f : known_formats()) EXPECT_EQ(&format_info(f.format), &f);
}

TEST(Format, UnknownNameIsAClearError) {
  try {
    vk_format("rgba9f");
    FAIL() << "expected GpuError";
  } catch (const GpuError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("unknown texel format 'rgba9f'; known formats: r8, rg8, rgba8,", 0), 0u) << m;
    EXPECT_NE(m.find("d32f"), std::string::npos) << m;
  }
  EXPECT_THROW(format_info(VK_FORMAT_BC7_SRGB_BLOCK), GpuError);
}

TEST(Format, HalfFloatConversionRoundsToNearestEven) {
  EXPECT_EQ(float_to_half(1.0f), 0x3c00);
  EXPECT_EQ(float_to_half(-2.0f), 0xc000);
  EXPECT_EQ(float_to_half(65504.0f), 0x7bff);
  EXPECT_EQ(float_to_half(65520.0f), 0x7c00);  // rounds up to infinity
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -24)), 0x0001);  // smallest subnormal
  EXPECT_EQ(float_to_half(std::ldexp(1.0f, -25)), 0x0000);  // a tie rounds to even: zero
  EXPECT_EQ(float_to_half(std::ldexp(1.5f, -25)), 0x0001);
  EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3c00);  // tie to even
  EXPECT_EQ(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)), 0x3c02);
  EXPECT_TRUE(std::isnan(half_to_float(float_to_half(std::numeric_limits<float>::quiet_NaN()))));
  EXPECT_EQ(half_to_float(float_to_half(-std::numeric_limits<float>::infinity())), -std::numeric_limits<float>::infinity());
  for (uint32_t bits = 0; bits < 0x7c00; ++bits)  // every finite positive half survives a round trip
    ASSERT_EQ(float_to_half(half_to_float(static_cast<uint16_t>(bits))), bits);
}

std::vector<float> round_trip(std::string_view format, const std::vector<float>& rgba) {
  const FormatInfo& f = format_info(format);
  std::vector<std::byte> bytes(rgba.size() / 4 * f.bytes_per_texel);
  encode_texels(f, rgba, bytes);
  std::vector<float> back(rgba.size());
  decode_texels(f, bytes, back);
  return back;
}

TEST(Format, TexelsRoundTripWithinEachFormatsPrecision) {
  const std::vector<float> texel = {0.2f, 0.5f, 0.8f, 0.4f};
  // Half a step of each format, plus a little for float rounding at exact ties.
  const float step8 = 0.501f / 255, step_snorm = 0.501f / 127, step10 = 0.501f / 1023;
  auto near = [](const std::vector<float>& got, const std::vector<float>& want, float tolerance) {
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], tolerance) << "channel " << i;
  };
  near(round_trip("rgba8", texel), texel, step8);
  near(round_trip("rgba8_srgb", texel), texel, 0.01f);  // sRGB steps are at most ~1/100 here
  near(round_trip("rgba8_snorm", {-0.2f, 0.5f, -1.5f, 1}), {-0.2f, 0.5f, -1, 1}, step_snorm);
  near(round_trip("rgb10a2", {0.2f, 0.5f, 0.8f, 0.4f}), {0.2f, 0.5f, 0.8f, 1.0f / 3}, step10);
  near(round_trip("rgba16f", texel), texel, 1e-3f);
  EXPECT_EQ(round_trip("rgba32f", texel), texel);
  // Missing channels read as 0, alpha as 1.
  EXPECT_EQ(round_trip("r32f", texel), (std::vector<float>{0.2f, 0, 0, 1}));
  near(round_trip("rg8", texel), {0.2f, 0.5f, 0, 1}, step8);
  // NaN in a normalized format becomes 0; out-of-range values clamp.
  EXPECT_EQ(round_trip("r8", {std::numeric_limits<float>::quiet_NaN(), 0, 0, 0})[0], 0);
  EXPECT_EQ(round_trip("r8", {7, 0, 0, 0})[0], 1);
  EXPECT_THROW(round_trip("rgba8", {1, 2, 3}), GpuError);
}

}  // namespace
}  // namespace lg::test
