// The plan's barriers as Vulkan barriers: stages, access and layouts map one to one; buffers
// get buffer barriers, or a global one when they take over aliased bytes; a batch records
// once and starts over.
#include <gtest/gtest.h>

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_barriers.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

TEST(PlanBarriers, StagesAccessAndLayoutsMapOneToOne) {
  EXPECT_EQ(vk_stages(stage_none), VK_PIPELINE_STAGE_2_NONE);
  EXPECT_EQ(vk_stages(stage_compute_shader | stage_fragment_shader),
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
  EXPECT_EQ(vk_stages(stage_color_attachment_output), VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
  EXPECT_EQ(vk_stages(stage_early_fragment_tests | stage_late_fragment_tests),
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT);

  EXPECT_EQ(vk_access(access_none), VK_ACCESS_2_NONE);
  EXPECT_EQ(vk_access(access_shader_sampled_read), VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  EXPECT_EQ(vk_access(access_shader_storage_read | access_shader_storage_write),
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  EXPECT_EQ(vk_access(access_color_attachment_read | access_color_attachment_write),
            VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  EXPECT_EQ(vk_access(access_depth_stencil_attachment_read | access_depth_stencil_attachment_write),
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);

  EXPECT_EQ(vk_layout(Layout::undefined), VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(vk_layout(Layout::general), VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(vk_layout(Layout::read_only), VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  EXPECT_EQ(vk_layout(Layout::attachment), VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL);
}

using BarrierBatchTest = GpuTest;

TEST_F(BarrierBatchTest, ImageBarriersCoverTheWholeImage) {
  Image image = Image::dedicated(context(), {.name = "chain", .format = VK_FORMAT_R16G16B16A16_SFLOAT, .width = 16,
                                             .height = 16, .mips = 5});
  BarrierBatch batch;
  batch.add({.before = 3, .resource = 0, .src_stages = stage_compute_shader, .src_access = access_shader_storage_write,
             .dst_stages = stage_fragment_shader, .dst_access = access_shader_sampled_read,
             .old_layout = Layout::general, .new_layout = Layout::read_only,
             .reason = BarrierReason::read_after_write},
            image);
  ASSERT_EQ(batch.image_barriers().size(), 1u);
  EXPECT_TRUE(batch.memory_barriers().empty());
  const VkImageMemoryBarrier2& b = batch.image_barriers()[0];
  EXPECT_EQ(b.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
  EXPECT_EQ(b.dstAccessMask, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  EXPECT_EQ(b.oldLayout, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(b.newLayout, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
  EXPECT_EQ(b.subresourceRange.levelCount, 5u);
  EXPECT_EQ(b.subresourceRange.aspectMask, VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT});
}

TEST_F(BarrierBatchTest, BuffersGetBufferBarriersOrAGlobalOneWhenAliased) {
  Buffer buffer = Buffer::dedicated(context(), {"sh", 144});
  Barrier after_write{.src_stages = stage_compute_shader, .src_access = access_shader_storage_write,
                      .dst_stages = stage_compute_shader, .dst_access = access_shader_storage_read,
                      .reason = BarrierReason::read_after_write};
  BarrierBatch batch;
  batch.add(after_write, buffer);
  ASSERT_EQ(batch.buffer_barriers().size(), 1u);
  EXPECT_EQ(batch.buffer_barriers()[0].buffer, buffer.handle());
  EXPECT_EQ(batch.buffer_barriers()[0].size, VK_WHOLE_SIZE);

  Barrier alias = after_write;
  alias.reason = BarrierReason::alias;
  batch.add(alias, buffer);
  EXPECT_EQ(batch.buffer_barriers().size(), 1u);
  EXPECT_EQ(batch.memory_barriers().size(), 1u);

  submitter().run([&](VkCommandBuffer cmd) { batch.record(cmd); });
  EXPECT_TRUE(batch.empty());
}

}  // namespace
}  // namespace lg::test
