// The context: creation on lavapipe with validation, picking a device by name, adopting a
// host's device without destroying it, and the device-memory total.
#include <gtest/gtest.h>

#include <cstring>

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/memory.h"
#include "runtime/gpu/transfer.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using ContextTest = GpuTest;

TEST_F(ContextTest, CreatesAVulkan13DeviceWithValidation) {
  Context& c = context();
  EXPECT_TRUE(c.owns_device());
  EXPECT_TRUE(c.validation_enabled());
  EXPECT_GE(c.properties().apiVersion, VK_API_VERSION_1_3);
  EXPECT_NE(c.device_name().find("llvmpipe"), std::string_view::npos) << c.device_name();
  EXPECT_GT(c.timestamp_period_ns(), 0);
  EXPECT_GT(c.timestamp_valid_bits(), 0u);
  EXPECT_NE(c.cmd_push_descriptor_set, nullptr);
}

TEST_F(ContextTest, PicksADeviceByName) {
  Context by_name(ContextOptions{.validation = true, .device_name = "llvmpipe"});
  EXPECT_NE(by_name.device_name().find("llvmpipe"), std::string_view::npos);
  EXPECT_TRUE(by_name.take_validation_messages().empty());
}

TEST_F(ContextTest, NoDeviceOfThatNameIsAnErrorListingTheDevices) {
  try {
    Context none(ContextOptions{.device_name = "no such GPU"});
    FAIL() << "expected GpuError";
  } catch (const GpuError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no suitable Vulkan device named like 'no such GPU'"), std::string::npos) << message;
    EXPECT_NE(message.find("llvmpipe"), std::string::npos) << message;
    EXPECT_NE(message.find("its name does not contain"), std::string::npos) << message;
  }
}

// The host keeps its device: work runs through the adopted context, and destroying that
// context leaves the host's device working.
TEST_F(ContextTest, AdoptsAHostDeviceAndLeavesItAlive) {
  Context& host = context();
  {
    Context adopted(HostDevice{host.instance(), host.physical_device(), host.device(), host.queue(), host.queue_family()});
    EXPECT_FALSE(adopted.owns_device());
    EXPECT_EQ(adopted.device(), host.device());
    Submitter submitter(adopted);
    PipelineCache cache(adopted);
    Buffer in = Buffer::dedicated(adopted, {"in", 4 * sizeof(float)});
    Buffer out = Buffer::dedicated(adopted, {"out", 4 * sizeof(float)});
    const float values[4] = {1, 2, 3, 4};
    upload_buffer(submitter, in, std::as_bytes(std::span(values)));
    const Pipeline& p = cache.compute({"scale", shader("scale_buffer.comp"),
                                       {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}});
    submitter.run([&](VkCommandBuffer cmd) {
      const DescriptorWrite writes[] = {storage_buffer(0, in.handle()), storage_buffer(1, out.handle())};
      bind_pipeline(adopted, cmd, p, writes);
      vkCmdDispatch(cmd, 1, 1, 1);
    });
    auto bytes = read_buffer(submitter, out);
    float result[4];
    std::memcpy(result, bytes.data(), sizeof result);
    EXPECT_EQ(result[0], 3);
    EXPECT_EQ(result[3], 9);
  }
  Image still = Image::dedicated(host, {.name = "after adoption", .format = VK_FORMAT_R32_SFLOAT, .width = 2, .height = 1});
  const std::vector<float> texels = {1, 0, 0, 1, 2, 0, 0, 1};
  upload_image(submitter(), still, texels, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(read_image(submitter(), still, VK_IMAGE_LAYOUT_GENERAL), texels);
  EXPECT_THROW(read_image(submitter(), still, VK_IMAGE_LAYOUT_UNDEFINED), GpuError);
}

TEST_F(ContextTest, CountsDeviceMemoryInUse) {
  const uint64_t before = context().device_memory_used();
  {
    DeviceMemory block(context(), 1 << 20, ~0u, MemoryUse::device_local, "block 0");
    EXPECT_EQ(context().device_memory_used(), before + (1 << 20));
    Buffer staging = Buffer::dedicated(context(), {"staging", 1000}, MemoryUse::upload);
    EXPECT_NE(staging.mapped(), nullptr);
    EXPECT_GE(context().device_memory_used(), before + (1 << 20) + 1000);
    DeviceMemory moved = std::move(block);
    EXPECT_GE(context().device_memory_used(), before + (1 << 20) + 1000);
  }
  EXPECT_EQ(context().device_memory_used(), before);
}

TEST_F(ContextTest, EmptyBlocksHoldNothing) {
  DeviceMemory empty(context(), 0, ~0u, MemoryUse::device_local, "block 1");
  EXPECT_EQ(empty.handle(), VK_NULL_HANDLE);
  try {
    Buffer::placed(context(), {"sh", 256}, empty, 0, 256);
    FAIL() << "expected GpuError";
  } catch (const GpuError& e) {
    EXPECT_STREQ(e.what(), "'sh' is placed in block 1, which holds no memory (size 0)");
  }
}

}  // namespace
}  // namespace lg::test
