#include "runtime/gpu/plan_barriers.h"

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

VkPipelineStageFlags2 vk_stages(uint32_t stages) {
  VkPipelineStageFlags2 out = VK_PIPELINE_STAGE_2_NONE;
  if (stages & stage_compute_shader) out |= VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  if (stages & stage_fragment_shader) out |= VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
  if (stages & stage_color_attachment_output) out |= VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  if (stages & stage_early_fragment_tests) out |= VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT;
  if (stages & stage_late_fragment_tests) out |= VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  return out;
}

VkAccessFlags2 vk_access(uint32_t access) {
  VkAccessFlags2 out = VK_ACCESS_2_NONE;
  if (access & access_shader_sampled_read) out |= VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  if (access & access_shader_storage_read) out |= VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
  if (access & access_shader_storage_write) out |= VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  if (access & access_color_attachment_read) out |= VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
  if (access & access_color_attachment_write) out |= VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  if (access & access_depth_stencil_attachment_read) out |= VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
  if (access & access_depth_stencil_attachment_write) out |= VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  if (access & access_uniform_read) out |= VK_ACCESS_2_UNIFORM_READ_BIT;
  return out;
}

VkImageLayout vk_layout(Layout layout) {
  switch (layout) {
    case Layout::general: return VK_IMAGE_LAYOUT_GENERAL;
    case Layout::read_only: return VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL;
    case Layout::attachment: return VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL;
    case Layout::undefined:
    case Layout::none: break;
  }
  return VK_IMAGE_LAYOUT_UNDEFINED;
}

void BarrierBatch::add_memory(const Barrier& barrier) {
  auto m = vk_struct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
  m.srcStageMask = vk_stages(barrier.src_stages);
  m.srcAccessMask = vk_access(barrier.src_access);
  m.dstStageMask = vk_stages(barrier.dst_stages);
  m.dstAccessMask = vk_access(barrier.dst_access);
  memory_.push_back(m);
}

void BarrierBatch::add(const Barrier& barrier, const Image& image) {
  // The previous holders of aliased bytes are other resources: an image barrier covers only
  // its own image, so their writes are waited for globally.
  if (barrier.reason == BarrierReason::alias) add_memory(barrier);
  auto b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  // The same source stages order the layout transition after the previous holders' work.
  b.srcStageMask = vk_stages(barrier.src_stages);
  b.srcAccessMask = vk_access(barrier.src_access);
  b.dstStageMask = vk_stages(barrier.dst_stages);
  b.dstAccessMask = vk_access(barrier.dst_access);
  b.oldLayout = vk_layout(barrier.old_layout);
  b.newLayout = vk_layout(barrier.new_layout);
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.handle();
  b.subresourceRange = image.whole_range();
  images_.push_back(b);
}

void BarrierBatch::add(const Barrier& barrier, const Buffer& buffer) {
  if (barrier.reason == BarrierReason::alias) {
    add_memory(barrier);
    return;
  }
  auto b = vk_struct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
  b.srcStageMask = vk_stages(barrier.src_stages);
  b.srcAccessMask = vk_access(barrier.src_access);
  b.dstStageMask = vk_stages(barrier.dst_stages);
  b.dstAccessMask = vk_access(barrier.dst_access);
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = buffer.handle();
  b.size = VK_WHOLE_SIZE;
  buffers_.push_back(b);
}

void BarrierBatch::record(VkCommandBuffer cmd) {
  if (empty()) return;
  auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.memoryBarrierCount = static_cast<uint32_t>(memory_.size());
  dep.pMemoryBarriers = memory_.data();
  dep.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers_.size());
  dep.pBufferMemoryBarriers = buffers_.data();
  dep.imageMemoryBarrierCount = static_cast<uint32_t>(images_.size());
  dep.pImageMemoryBarriers = images_.data();
  vkCmdPipelineBarrier2(cmd, &dep);
  memory_.clear();
  images_.clear();
  buffers_.clear();
}

}  // namespace lg
