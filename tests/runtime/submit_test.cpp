// Submission, timing and caching: timestamps measure positive GPU durations, a submission that
// cannot finish times out with an error instead of hanging, and the pipeline cache hands back
// the same pipeline for the same SPIR-V and state.
#include <gtest/gtest.h>

#include <chrono>

#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/gpu/timestamps.h"
#include "runtime/gpu/vk_struct.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using SubmitTest = GpuTest;

TEST_F(SubmitTest, TimestampsGivePositiveDurationsPerScope) {
  const uint32_t size = 256;
  Image image = Image::dedicated(context(), {.name = "timed", .format = vk_format("rgba16f"), .width = size, .height = size});
  const Pipeline& p = compute("fill_rgba16f.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof(float));
  TimestampQueries timer(context(), 4);
  submitter().run([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    BarrierBatch barriers;
    barriers.add({.dst_stages = stage_compute_shader, .dst_access = access_shader_storage_write,
                  .old_layout = Layout::undefined, .new_layout = Layout::general},
                 image);
    barriers.record(cmd);
    const DescriptorWrite writes[] = {storage_image(0, image.view())};
    bind_pipeline(context(), cmd, p, writes);
    push_constants(cmd, p, 1.0f);
    for (const char* name : {"fill/first", "fill/second"}) {
      uint32_t scope = timer.begin(cmd, name);
      vkCmdDispatch(cmd, size / 8, size / 8, 1);
      timer.end(cmd, scope);
      barriers.add({.src_stages = stage_compute_shader, .src_access = access_shader_storage_write,
                    .dst_stages = stage_compute_shader, .dst_access = access_shader_storage_write,
                    .old_layout = Layout::general, .new_layout = Layout::general,
                    .reason = BarrierReason::write_after_write},
                   image);
      barriers.record(cmd);
    }
  });
  std::vector<ScopeTime> times = timer.results();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[0].name, "fill/first");
  EXPECT_EQ(times[1].name, "fill/second");
  for (const ScopeTime& t : times) EXPECT_GT(t.milliseconds, 0) << t.name;
}

TEST_F(SubmitTest, TooManyTimestampScopesIsAnError) {
  TimestampQueries timer(context(), 1);
  submitter().run([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    timer.end(cmd, timer.begin(cmd, "one"));
    EXPECT_THROW(timer.begin(cmd, "two"), GpuError);
  });
}

// The GPU waits on an event only the host sets: the wait times out, and once the event is set
// the submitter carries on.
TEST_F(SubmitTest, ATimeoutIsAnErrorNotAHang) {
  auto info = vk_struct<VkEventCreateInfo>(VK_STRUCTURE_TYPE_EVENT_CREATE_INFO);
  VkEvent event;
  ASSERT_EQ(vkCreateEvent(context().device(), &info, nullptr, &event), VK_SUCCESS);
  try {
    submitter().run(
        [&](VkCommandBuffer cmd) {
          auto barrier = vk_struct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
          barrier.srcStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
          barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
          auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
          dep.memoryBarrierCount = 1;
          dep.pMemoryBarriers = &barrier;
          vkCmdWaitEvents2(cmd, 1, &event, &dep);
        },
        std::chrono::milliseconds(50));
    ADD_FAILURE() << "expected a timeout";
  } catch (const GpuError& e) {
    EXPECT_STREQ(e.what(), "vkWaitForFences timed out after 50 ms waiting for a one-shot submission");
    EXPECT_EQ(e.result(), VK_TIMEOUT);
  }
  ASSERT_EQ(vkSetEvent(context().device(), event), VK_SUCCESS);
  submitter().run([](VkCommandBuffer) {});
  vkDestroyEvent(context().device(), event, nullptr);
}

TEST_F(SubmitTest, PipelineCacheReturnsTheSamePipelineForTheSameSpirvAndState) {
  PipelineCache cache(context());  // not the shared one, which other tests of this process fill
  const std::vector<DescriptorBinding> image = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}};
  const Pipeline& a = cache.compute({"a", shader("fill_rgba16f.comp"), image, sizeof(float)});
  const Pipeline& b = cache.compute({"b", shader("fill_rgba16f.comp"), image, sizeof(float)});
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(a.handle, b.handle);
  EXPECT_EQ(cache.size(), 1u);
  // Other state or other SPIR-V: another pipeline.
  const Pipeline& c = cache.compute({"c", shader("fill_rgba16f.comp"), image, 2 * sizeof(float)});
  const Pipeline& d = cache.compute({"d", shader("fill_r32f.comp"), image, sizeof(float)});
  EXPECT_NE(c.handle, a.handle);
  EXPECT_NE(d.handle, a.handle);
  EXPECT_EQ(cache.size(), 3u);

  GraphicsPipelineDesc g{.name = "gradient", .vertex_shader = shader("fullscreen.vert"),
                         .fragment_shader = shader("gradient.frag"), .push_constant_bytes = 12,
                         .color_formats = {VK_FORMAT_R16G16B16A16_SFLOAT}};
  const Pipeline& g1 = cache.graphics(g);
  EXPECT_EQ(&cache.graphics(g), &g1);
  g.blend = Blend::additive;
  EXPECT_NE(cache.graphics(g).handle, g1.handle);
  EXPECT_EQ(cache.size(), 5u);
}

TEST_F(SubmitTest, UnknownShaderAndNonSpirvAreErrors) {
  try {
    shader("missing.comp");
    FAIL() << "expected GpuError";
  } catch (const GpuError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no embedded shader 'tests/runtime/shaders/missing.comp'"), std::string::npos) << m;
    EXPECT_NE(m.find("tests/runtime/shaders/fill_r32f.comp"), std::string::npos) << m;
  }
  const uint32_t text[] = {0x6c756d61, 0x67726170, 0x68000000, 0, 0};
  EXPECT_THROW(pipelines().compute({"bad", text, {}, 0}), GpuError);
}

}  // namespace
}  // namespace lg::test
