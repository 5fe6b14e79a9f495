// Barriers recorded directly rather than from a plan (plan_barriers.h records those): around
// uploads and readbacks, for first-frame clears, between the dispatches inside one pass.
// Without scopes they wait for all earlier work and make it visible to all later work.
#pragma once

#include <vulkan/vulkan.h>

namespace lg {

class Image;

struct SyncScope {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkAccessFlags2 access = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
};

// The whole image (every mip and layer) from layout `from` to `to`.
void image_barrier(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to, SyncScope before = {},
                   SyncScope after = {});
void memory_barrier(VkCommandBuffer cmd, SyncScope before = {}, SyncScope after = {});

}  // namespace lg
