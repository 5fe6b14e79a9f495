// Compute shaders embedded at build time write images and buffers whose contents are known
// functions of the coordinates; read back, they must match exactly (every value written is
// exactly representable in its format).
#include <gtest/gtest.h>

#include <cstring>

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/sampler.h"
#include "runtime/gpu/transfer.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using ComputeTest = GpuTest;

// Readback's own barrier waits for the dispatches, so none is recorded after them.
void to_general(VkCommandBuffer cmd, const Image& image) {
  image_barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
                {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}

TEST_F(ComputeTest, FillsAnImageWithAFunctionOfTheTexelCoordinate) {
  const uint32_t w = 48, h = 40;  // not multiples of the 8x8 group: the edge groups are partial
  Image image = Image::dedicated(context(), {.name = "fill", .format = vk_format("rgba16f"), .width = w, .height = h});
  const Pipeline& p = compute("fill_rgba16f.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof(float));
  submitter().run([&](VkCommandBuffer cmd) {
    to_general(cmd, image);
    const DescriptorWrite writes[] = {storage_image(0, image.view())};
    bind_pipeline(context(), cmd, p, writes);
    push_constants(cmd, p, 0.75f);
    vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
  });
  std::vector<float> texels = read_image(submitter(), image, VK_IMAGE_LAYOUT_GENERAL);
  ASSERT_EQ(texels.size(), size_t{w} * h * 4);
  int wrong = 0;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float* t = &texels[(y * w + x) * 4];
      const float want[4] = {x / 256.0f, y / 256.0f, (x ^ y) / 256.0f, 0.75f};
      if (std::memcmp(t, want, sizeof want) != 0 && ++wrong <= 5)
        ADD_FAILURE() << "texel " << x << "," << y << ": " << t[0] << " " << t[1] << " " << t[2] << " " << t[3];
    }
  EXPECT_EQ(wrong, 0);
}

TEST_F(ComputeTest, WritesEveryFaceOfACubeMap) {
  const uint32_t size = 16;
  Image cube = Image::dedicated(context(), {.name = "cube",
                                            .kind = ImageKind::cube,
                                            .format = vk_format("rgba32f"),
                                            .width = size,
                                            .height = size,
                                            .mips = 2,
                                            .layers = 6});
  const Pipeline& p = compute("fill_layers.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
  submitter().run([&](VkCommandBuffer cmd) {
    to_general(cmd, cube);
    // Storage access to a cube goes through a 2D array view of its faces.
    const DescriptorWrite writes[] = {
        storage_image(0, cube.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .mip_count = 1}))};
    bind_pipeline(context(), cmd, p, writes);
    vkCmdDispatch(cmd, size / 8, size / 8, 6);
  });
  EXPECT_NE(cube.view(), VK_NULL_HANDLE);  // a cube view for sampling
  for (uint32_t face = 0; face < 6; ++face) {
    std::vector<float> texels = read_image(submitter(), cube, VK_IMAGE_LAYOUT_GENERAL, {.mip = 0, .layer = face});
    for (uint32_t y = 0; y < size; ++y)
      for (uint32_t x = 0; x < size; ++x) {
        const float* t = &texels[(y * size + x) * 4];
        ASSERT_TRUE(t[0] == x && t[1] == y && t[2] == face && t[3] == 1)
            << "face " << face << " texel " << x << "," << y;
      }
  }
}

TEST_F(ComputeTest, WritesA3DImage) {
  const uint32_t w = 8, h = 4, d = 12;
  Image volume = Image::dedicated(
      context(),
      {.name = "volume", .kind = ImageKind::image3d, .format = vk_format("r32f"), .width = w, .height = h, .depth = d});
  const Pipeline& p = compute("fill_volume.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
  submitter().run([&](VkCommandBuffer cmd) {
    to_general(cmd, volume);
    const DescriptorWrite writes[] = {storage_image(0, volume.view())};
    bind_pipeline(context(), cmd, p, writes);
    vkCmdDispatch(cmd, w / 4, h / 4, d / 4);
  });
  std::vector<float> texels = read_image(submitter(), volume, VK_IMAGE_LAYOUT_GENERAL);
  ASSERT_EQ(texels.size(), size_t{w} * h * d * 4);
  for (uint32_t z = 0; z < d; ++z)
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x)
        ASSERT_EQ(texels[((z * h + y) * w + x) * 4], x + 100.0f * y + 10000.0f * z) << x << "," << y << "," << z;
}

// An upload read through nearest and repeating samplers comes back exactly (rgba8 values
// k/255 survive the trip through the sampler and an rgba32f store).
TEST_F(ComputeTest, SamplesAnUploadedTexture) {
  const uint32_t w = 16, h = 8;
  Image source = Image::dedicated(context(), {.name = "source", .format = vk_format("rgba8"), .width = w, .height = h});
  Image target =
      Image::dedicated(context(), {.name = "target", .format = vk_format("rgba32f"), .width = w, .height = h});
  std::vector<float> texels(w * h * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<float>((i * 37) % 256) / 255;
  upload_image(submitter(), source, texels, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);

  Sampler sampler(context(), {.filter = Filter::nearest, .address = Address::repeat});
  const Pipeline& p =
      compute("sample.comp", {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
              2 * sizeof(float));
  submitter().run([&](VkCommandBuffer cmd) {
    to_general(cmd, target);
    const DescriptorWrite writes[] = {sampled_image(0, source.view(), sampler.handle()),
                                      storage_image(1, target.view())};
    bind_pipeline(context(), cmd, p, writes);
    const float shift[2] = {2, -1};  // whole repeats: the same texels
    push_constants(cmd, p, shift);
    vkCmdDispatch(cmd, w / 8, h / 8, 1);
  });
  std::vector<float> back = read_image(submitter(), target, VK_IMAGE_LAYOUT_GENERAL);
  for (size_t i = 0; i < texels.size(); ++i) ASSERT_NEAR(back[i], texels[i], 1e-6f) << "float " << i;
}

TEST_F(ComputeTest, ReadsAndWritesStorageBuffers) {
  const size_t count = 100;  // vec4s: two groups of 64, the second partial
  Buffer in = Buffer::dedicated(context(), {"coefficients in", count * 16});
  Buffer out = Buffer::dedicated(context(), {"coefficients out", count * 16});
  std::vector<float> values(count * 4);
  for (size_t i = 0; i < values.size(); ++i) values[i] = static_cast<float>(i) - 50.5f;
  upload_buffer(submitter(), in, std::as_bytes(std::span(values)));
  const Pipeline& p =
      compute("scale_buffer.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
  submitter().run([&](VkCommandBuffer cmd) {
    const DescriptorWrite writes[] = {storage_buffer(0, in.handle()), storage_buffer(1, out.handle())};
    bind_pipeline(context(), cmd, p, writes);
    vkCmdDispatch(cmd, 2, 1, 1);
  });
  std::vector<std::byte> bytes = read_buffer(submitter(), out);
  std::vector<float> result(count * 4);
  std::memcpy(result.data(), bytes.data(), bytes.size());
  for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(result[i], values[i] * 2 + 1) << i;
  EXPECT_EQ(read_buffer(submitter(), out, 16, 16).size(), 16u);
  EXPECT_THROW(read_buffer(submitter(), out, count * 16 - 8, 16), GpuError);
}

}  // namespace
}  // namespace lg::test
