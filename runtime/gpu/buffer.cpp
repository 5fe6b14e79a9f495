#include "runtime/gpu/buffer.h"

#include <utility>

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

Buffer::Buffer(Context& context, const BufferDesc& desc) : context_(&context), desc_(desc) {
  if (desc.size == 0) throw GpuError("buffer '" + desc.name + "' has size 0");
  auto info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = desc.size;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  vk_check(vkCreateBuffer(context.device(), &info, nullptr, &buffer_), "vkCreateBuffer",
           "for buffer '" + desc.name + "'");
  context.set_name(VK_OBJECT_TYPE_BUFFER, buffer_, desc.name);
}

Buffer Buffer::placed(Context& context, const BufferDesc& desc, const DeviceMemory& block, uint64_t offset,
                      uint64_t reserved) {
  Buffer buffer(context, desc);
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(context.device(), buffer.buffer_, &needs);
  check_placement(desc.name, needs, block, offset, reserved);
  vk_check(vkBindBufferMemory(context.device(), buffer.buffer_, block.handle(), offset), "vkBindBufferMemory",
           "for buffer '" + desc.name + "'");
  return buffer;
}

Buffer Buffer::dedicated(Context& context, const BufferDesc& desc, MemoryUse use) {
  Buffer buffer(context, desc);
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(context.device(), buffer.buffer_, &needs);
  buffer.own_memory_ = DeviceMemory(context, needs.size, needs.memoryTypeBits, use, "memory of buffer '" + desc.name + "'");
  vk_check(vkBindBufferMemory(context.device(), buffer.buffer_, buffer.own_memory_.handle(), 0), "vkBindBufferMemory",
           "for buffer '" + desc.name + "'");
  return buffer;
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    desc_ = std::move(other.desc_);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    own_memory_ = std::move(other.own_memory_);
  }
  return *this;
}

void Buffer::release() {
  if (!buffer_) return;
  vkDestroyBuffer(context_->device(), buffer_, nullptr);
  buffer_ = VK_NULL_HANDLE;
  own_memory_ = DeviceMemory();
}

}  // namespace lg
