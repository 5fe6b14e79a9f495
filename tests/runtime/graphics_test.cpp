// A graphics pipeline with dynamic rendering draws a full-screen triangle into a colour and a
// depth attachment; the colour is a known function of the pixel and the depth test keeps the
// nearer of two draws (reversed Z: greater is nearer).
#include <gtest/gtest.h>

#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/gpu/transfer.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using GraphicsTest = GpuTest;

struct Constants {
  float size[2];
  float depth;
};

TEST_F(GraphicsTest, DrawsAFullScreenPassWithDepth) {
  const uint32_t w = 64, h = 32;
  Image color = Image::dedicated(context(), {.name = "color", .format = vk_format("rgba16f"), .width = w, .height = h});
  Image depth = Image::dedicated(context(), {.name = "depth", .format = vk_format("d32f"), .width = w, .height = h});
  GraphicsPipelineDesc desc;
  desc.name = "gradient";
  desc.vertex_shader = shader("fullscreen.vert");
  desc.fragment_shader = shader("gradient.frag");
  desc.push_constant_bytes = sizeof(Constants);
  desc.color_formats = {color.desc().format};
  desc.depth_format = depth.desc().format;
  desc.depth_test = desc.depth_write = true;
  const Pipeline& p = pipelines().graphics(desc);

  submitter().run([&](VkCommandBuffer cmd) {
    // The plan's first-use barriers of a colour and a depth attachment.
    BarrierBatch barriers;
    barriers.add({.before = 0,
                  .dst_stages = stage_color_attachment_output,
                  .dst_access = access_color_attachment_write,
                  .old_layout = Layout::undefined,
                  .new_layout = Layout::attachment},
                 color);
    barriers.add({.before = 0,
                  .dst_stages = stage_early_fragment_tests | stage_late_fragment_tests,
                  .dst_access = access_depth_stencil_attachment_read | access_depth_stencil_attachment_write,
                  .old_layout = Layout::undefined,
                  .new_layout = Layout::attachment},
                 depth);
    barriers.record(cmd);

    VkRenderingAttachmentInfo color_attachment = cleared_attachment(color.view(), {});
    VkRenderingAttachmentInfo depth_attachment = cleared_attachment(depth.view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(w, h, {&color_attachment, 1}, &depth_attachment);
    vkCmdBeginRendering(cmd, &rendering);
    bind_pipeline(context(), cmd, p);
    set_viewport(cmd, w, h);
    push_constants(cmd, p, Constants{{float(w), float(h)}, 0.25f});
    vkCmdDraw(cmd, 3, 1, 0, 0);
    push_constants(cmd, p, Constants{{float(w), float(h)}, 0.125f});  // farther: hidden
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
  });

  std::vector<float> pixels = read_image(submitter(), color, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL);
  std::vector<float> depths = read_image(submitter(), depth, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float* c = &pixels[(y * w + x) * 4];
      // Pixel centres (x + 0.5) / w are exact in half precision for these sizes.
      ASSERT_EQ(c[0], (x + 0.5f) / w) << x << "," << y;
      ASSERT_EQ(c[1], (y + 0.5f) / h) << x << "," << y;
      ASSERT_EQ(c[2], 0.25f) << x << "," << y;
      ASSERT_EQ(c[3], 1.0f) << x << "," << y;
      ASSERT_EQ(depths[(y * w + x) * 4], 0.25f) << x << "," << y;
    }
}

}  // namespace
}  // namespace lg::test
