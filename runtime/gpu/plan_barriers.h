// Turns the plan's barriers (graph/compiler/barrier.h: synchronization2 stages, access and
// layouts as plain data) into Vulkan barriers and records them, following what
// docs/graph-format.md asks of the runtime: an `alias` barrier waits for the previous holders
// of the bytes with a global memory barrier beside the new image's layout transition.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "graph/compiler/barrier.h"

namespace lg {

class Buffer;
class Image;

VkPipelineStageFlags2 vk_stages(uint32_t stages);  // a mask of lg::Stage
VkAccessFlags2 vk_access(uint32_t access);         // a mask of lg::Access
VkImageLayout vk_layout(Layout layout);

// The barriers before one pass, gathered and then recorded in one vkCmdPipelineBarrier2.
class BarrierBatch {
 public:
  void add(const Barrier& barrier, const Image& image);
  void add(const Barrier& barrier, const Buffer& buffer);
  // Records what was added (nothing when empty) and starts over.
  void record(VkCommandBuffer cmd);

  bool empty() const { return memory_.empty() && images_.empty() && buffers_.empty(); }
  const std::vector<VkMemoryBarrier2>& memory_barriers() const { return memory_; }
  const std::vector<VkImageMemoryBarrier2>& image_barriers() const { return images_; }
  const std::vector<VkBufferMemoryBarrier2>& buffer_barriers() const { return buffers_; }

 private:
  void add_memory(const Barrier& barrier);
  std::vector<VkMemoryBarrier2> memory_;
  std::vector<VkImageMemoryBarrier2> images_;
  std::vector<VkBufferMemoryBarrier2> buffers_;
};

}  // namespace lg
