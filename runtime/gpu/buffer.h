// Buffers: placed in a plan memory block at the plan's offset (SH coefficients, scalars), or
// with memory of their own, device-local or host-visible and mapped (staging, readback).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "runtime/gpu/memory.h"

namespace lg {

class Context;

inline constexpr VkBufferUsageFlags default_buffer_usage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
    VK_BUFFER_USAGE_TRANSFER_DST_BIT;

struct BufferDesc {
  std::string name{};  // in errors and validation messages
  uint64_t size = 0;
  VkBufferUsageFlags usage = default_buffer_usage;
};

class Buffer {
 public:
  // Bound at `offset` of a plan block whose placement reserves `reserved` bytes; throws
  // GpuError naming the buffer if it does not fit there.
  static Buffer placed(Context& context, const BufferDesc& desc, const DeviceMemory& block, uint64_t offset,
                       uint64_t reserved);
  // With memory of its own; host-visible uses keep it mapped at mapped().
  static Buffer dedicated(Context& context, const BufferDesc& desc, MemoryUse use = MemoryUse::device_local);

  Buffer() = default;
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_; }
  const BufferDesc& desc() const { return desc_; }
  uint64_t size() const { return desc_.size; }
  std::byte* mapped() const { return own_memory_.mapped(); }

 private:
  Buffer(Context& context, const BufferDesc& desc);  // created, not bound
  void release();

  Context* context_ = nullptr;
  BufferDesc desc_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  DeviceMemory own_memory_;  // dedicated buffers only
};

}  // namespace lg
