// Binding a pipeline and its resources while recording: the pipeline, its push descriptors
// (set 0) and its push constants.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "runtime/gpu/pipeline.h"

namespace lg {

class Context;

struct DescriptorWrite {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  VkDescriptorImageInfo image{};
  VkDescriptorBufferInfo buffer{};
};

// Storage images are in the GENERAL layout, as the plan's barriers leave them.
DescriptorWrite storage_image(uint32_t binding, VkImageView view);
DescriptorWrite sampled_image(uint32_t binding, VkImageView view, VkSampler sampler,
                              VkImageLayout layout = VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL);
DescriptorWrite storage_buffer(uint32_t binding, VkBuffer buffer, uint64_t offset = 0, uint64_t range = VK_WHOLE_SIZE);
DescriptorWrite uniform_buffer(uint32_t binding, VkBuffer buffer, uint64_t offset = 0, uint64_t range = VK_WHOLE_SIZE);

// Binds `pipeline` and pushes `writes` into its set 0.
void bind_pipeline(const Context& context, VkCommandBuffer cmd, const Pipeline& pipeline,
                   std::span<const DescriptorWrite> writes = {});

// Pushes `bytes` of push constants from offset 0; throws GpuError when the pipeline has fewer.
void push_constants(VkCommandBuffer cmd, const Pipeline& pipeline, const void* data, uint32_t bytes);
template <typename T>
void push_constants(VkCommandBuffer cmd, const Pipeline& pipeline, const T& value) {
  push_constants(cmd, pipeline, &value, sizeof value);
}

}  // namespace lg
