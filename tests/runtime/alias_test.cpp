// Aliasing made real: two images bound at the same offset of one memory block, written one
// after the other with the plan's alias barrier between them, pass synchronization validation;
// without the barrier the validation layer reports the hazard (so the tests would catch it).
// Placements that cannot hold their resource are clear errors naming it.
#include <gtest/gtest.h>

#include <algorithm>

#include "graph/plan_format.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/plan_barriers.h"
#include "runtime/gpu/transfer.h"
#include "tests/runtime/gpu_test.h"

namespace lg::test {
namespace {

using AliasTest = GpuTest;

constexpr uint32_t size = 32;

struct AliasedPair {
  DeviceMemory block;
  Image first, second;  // rgba16f and r32f at offset 0 of `block`
};

AliasedPair make_pair(Context& context) {
  ImageDesc first{.name = "first", .format = vk_format("rgba16f"), .width = size, .height = size};
  ImageDesc second{.name = "second", .format = vk_format("r32f"), .width = size, .height = size};
  VkMemoryRequirements a = Image::requirements(context, first), b = Image::requirements(context, second);
  AliasedPair pair;
  pair.block = DeviceMemory(context, std::max(a.size, b.size), a.memoryTypeBits & b.memoryTypeBits,
                            MemoryUse::device_local, "block 0");
  pair.first = Image::placed(context, first, pair.block, 0, a.size);
  pair.second = Image::placed(context, second, pair.block, 0, b.size);
  return pair;
}

// The plan's barriers for a resource written by compute: its first use, or taking over the
// bytes of one written by compute.
Barrier first_write(BarrierReason reason) {
  Barrier b;
  b.reason = reason;
  if (reason == BarrierReason::alias) {
    b.src_stages = stage_compute_shader;
    b.src_access = access_shader_storage_write;
  }
  b.dst_stages = stage_compute_shader;
  b.dst_access = access_shader_storage_write;
  b.old_layout = Layout::undefined;
  b.new_layout = Layout::general;
  return b;
}

class AliasWrites : public AliasTest {
 protected:
  void write_both(AliasedPair& pair, bool with_alias_barrier) {
    const Pipeline& fill16 = compute("fill_rgba16f.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof(float));
    const Pipeline& fill32 = compute("fill_r32f.comp", {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof(float));
    submitter().run([&](VkCommandBuffer cmd) {
      BarrierBatch barriers;
      barriers.add(first_write(BarrierReason::first_use), pair.first);
      barriers.record(cmd);
      const DescriptorWrite first[] = {storage_image(0, pair.first.view())};
      bind_pipeline(context(), cmd, fill16, first);
      push_constants(cmd, fill16, 1.0f);
      vkCmdDispatch(cmd, size / 8, size / 8, 1);

      barriers.add(first_write(with_alias_barrier ? BarrierReason::alias : BarrierReason::first_use), pair.second);
      barriers.record(cmd);
      const DescriptorWrite second[] = {storage_image(0, pair.second.view())};
      bind_pipeline(context(), cmd, fill32, second);
      push_constants(cmd, fill32, 0.5f);
      vkCmdDispatch(cmd, size / 8, size / 8, 1);
    });
  }
};

TEST_F(AliasWrites, ShareBytesAndPassSynchronizationValidation) {
  AliasedPair pair = make_pair(context());
  EXPECT_EQ(pair.first.memory(), pair.second.memory());
  EXPECT_EQ(pair.first.memory_offset(), pair.second.memory_offset());
  write_both(pair, true);
  std::vector<float> texels = read_image(submitter(), pair.second, VK_IMAGE_LAYOUT_GENERAL);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) ASSERT_EQ(texels[(y * size + x) * 4], x * 1000 + y + 0.5f) << x << "," << y;
}

TEST_F(AliasWrites, WithoutTheAliasBarrierValidationReportsTheHazard) {
  AliasedPair pair = make_pair(context());
  write_both(pair, false);
  auto messages = context().take_validation_messages();
  const bool hazard = std::any_of(messages.begin(), messages.end(), [](const ValidationMessage& m) {
    return m.id.find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos;
  });
  EXPECT_TRUE(hazard) << "expected a write-after-write hazard; got:" << describe(messages);
}

TEST_F(AliasTest, BarrierForAliasWaitsForThePreviousHolderGlobally) {
  AliasedPair pair = make_pair(context());
  BarrierBatch batch;
  batch.add(first_write(BarrierReason::alias), pair.second);
  ASSERT_EQ(batch.memory_barriers().size(), 1u);
  ASSERT_EQ(batch.image_barriers().size(), 1u);
  EXPECT_EQ(batch.memory_barriers()[0].srcAccessMask, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  EXPECT_EQ(batch.image_barriers()[0].srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
  EXPECT_EQ(batch.image_barriers()[0].oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(batch.image_barriers()[0].image, pair.second.handle());
}

// ---- placements that do not fit ----

std::string placement_error(Context& context, uint64_t block_size, uint64_t offset, uint64_t reserved) {
  DeviceMemory block(context, block_size, ~0u, MemoryUse::device_local, "block 0");
  try {
    Image::placed(context, {.name = "bloom/chain", .format = vk_format("rgba16f"), .width = 64, .height = 64}, block,
                  offset, reserved);
  } catch (const GpuError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(AliasTest, PlacementTooSmallNamesTheResource) {
  const uint64_t needs = Image::requirements(context(), {.format = vk_format("rgba16f"), .width = 64, .height = 64}).size;
  const std::string m = placement_error(context(), 1 << 20, 0, 1000);
  EXPECT_EQ(m, "'bloom/chain' needs " + format_bytes(needs) + " (" + std::to_string(needs) +
                   " bytes) of device memory but its placement at offset 0 of block 0 reserves only 1000 B")
      << m;
}

TEST_F(AliasTest, PlacementRunningPastTheBlockNamesTheResource) {
  const std::string m = placement_error(context(), 64 * 1024, 40 * 1024, 1 << 20);  // needs 32 KiB
  EXPECT_NE(m.find("'bloom/chain'"), std::string::npos) << m;
  EXPECT_NE(m.find("runs past its end"), std::string::npos) << m;
}

TEST_F(AliasTest, MisalignedPlacementNamesTheResource) {
  const VkMemoryRequirements needs =
      Image::requirements(context(), {.format = vk_format("rgba16f"), .width = 64, .height = 64});
  ASSERT_GT(needs.alignment, 1u);
  const std::string m = placement_error(context(), 1 << 20, needs.alignment / 2, 1 << 19);
  EXPECT_NE(m.find("'bloom/chain' must start at a multiple of " + std::to_string(needs.alignment)), std::string::npos) << m;
}

TEST_F(AliasTest, BuffersArePlacedToo) {
  DeviceMemory block(context(), 4096, ~0u, MemoryUse::device_local, "block 1");
  Buffer a = Buffer::placed(context(), {"sh.sh", 144}, block, 0, 256);
  Buffer b = Buffer::placed(context(), {"scalar", 4}, block, 256, 256);
  EXPECT_NE(a.handle(), b.handle());
  EXPECT_EQ(a.mapped(), nullptr);
  EXPECT_THROW(Buffer::placed(context(), {"too big", 300}, block, 512, 256), GpuError);
}

}  // namespace
}  // namespace lg::test
