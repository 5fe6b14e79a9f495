#include "runtime/gpu/descriptors.h"

#include <string>
#include <vector>

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

DescriptorWrite storage_image(uint32_t binding, VkImageView view) {
  DescriptorWrite w{binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
  w.image = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
  return w;
}

DescriptorWrite sampled_image(uint32_t binding, VkImageView view, VkSampler sampler, VkImageLayout layout) {
  DescriptorWrite w{binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
  w.image = {sampler, view, layout};
  return w;
}

DescriptorWrite storage_buffer(uint32_t binding, VkBuffer buffer, uint64_t offset, uint64_t range) {
  DescriptorWrite w{binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  w.buffer = {buffer, offset, range};
  return w;
}

DescriptorWrite uniform_buffer(uint32_t binding, VkBuffer buffer, uint64_t offset, uint64_t range) {
  DescriptorWrite w{binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
  w.buffer = {buffer, offset, range};
  return w;
}

void bind_pipeline(const Context& context, VkCommandBuffer cmd, const Pipeline& pipeline,
                   std::span<const DescriptorWrite> writes) {
  vkCmdBindPipeline(cmd, pipeline.bind_point, pipeline.handle);
  if (writes.empty()) return;
  std::vector<VkWriteDescriptorSet> sets;
  sets.reserve(writes.size());
  for (const DescriptorWrite& w : writes) {
    auto s = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    s.dstBinding = w.binding;
    s.descriptorCount = 1;
    s.descriptorType = w.type;
    const bool buffer = w.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER || w.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (buffer) s.pBufferInfo = &w.buffer;
    else s.pImageInfo = &w.image;
    sets.push_back(s);
  }
  context.cmd_push_descriptor_set(cmd, pipeline.bind_point, pipeline.layout, 0, static_cast<uint32_t>(sets.size()),
                                  sets.data());
}

void push_constants(VkCommandBuffer cmd, const Pipeline& pipeline, const void* data, uint32_t bytes) {
  if (bytes > pipeline.push_constant_bytes)
    throw GpuError("pushing " + std::to_string(bytes) + " bytes of constants to a pipeline that takes " +
                   std::to_string(pipeline.push_constant_bytes));
  vkCmdPushConstants(cmd, pipeline.layout, pipeline.stages, 0, bytes, data);
}

}  // namespace lg
