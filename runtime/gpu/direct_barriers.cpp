#include "runtime/gpu/direct_barriers.h"

#include "runtime/gpu/image.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

void image_barrier(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to, SyncScope before,
                   SyncScope after) {
  auto b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  b.srcStageMask = before.stages;
  b.srcAccessMask = before.access;
  b.dstStageMask = after.stages;
  b.dstAccessMask = after.access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.handle();
  b.subresourceRange = image.whole_range();
  auto dependency = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

void memory_barrier(VkCommandBuffer cmd, SyncScope before, SyncScope after) {
  auto b = vk_struct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
  b.srcStageMask = before.stages;
  b.srcAccessMask = before.access;
  b.dstStageMask = after.stages;
  b.dstAccessMask = after.access;
  auto dependency = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace lg
