// Device memory: one VkDeviceMemory per plan memory block, into which images and buffers are
// bound at the plan's offsets (so the compiler's aliasing is real in device memory), and small
// dedicated allocations for standalone resources (staging, readback). Every allocation counts
// toward Context::device_memory_used().
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>

namespace lg {

class Context;

enum class MemoryUse : uint8_t {
  device_local,  // GPU-only: plan blocks, images
  upload,        // host-visible, written by the CPU (staging)
  readback,      // host-visible, read by the CPU; cached where the device offers it
};

class DeviceMemory {
 public:
  DeviceMemory() = default;  // empty: a block of size 0 holds nothing
  // `type_bits` limits the memory types (VkMemoryRequirements::memoryTypeBits of what will live
  // there); `name` ("block 0", "staging for 'sky.cube'") appears in errors.
  DeviceMemory(Context& context, uint64_t size, uint32_t type_bits, MemoryUse use, std::string name);
  ~DeviceMemory();
  DeviceMemory(DeviceMemory&& other) noexcept;
  DeviceMemory& operator=(DeviceMemory&& other) noexcept;

  VkDeviceMemory handle() const { return memory_; }
  uint64_t size() const { return size_; }
  uint32_t type_index() const { return type_index_; }
  const std::string& name() const { return name_; }
  std::byte* mapped() const { return mapped_; }  // host-visible memory stays mapped; else null

 private:
  void release();
  Context* context_ = nullptr;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  uint64_t size_ = 0;
  uint32_t type_index_ = 0;
  std::string name_;
  std::byte* mapped_ = nullptr;
};

// The first memory type in `type_bits` with the properties `use` needs; throws GpuError
// naming `what` when there is none.
uint32_t find_memory_type(const Context& context, uint32_t type_bits, MemoryUse use, const std::string& what);

// Throws GpuError naming `resource` unless it fits `reserved` bytes at `offset` of `memory`:
// its size, its alignment, its memory types, and the end of the block.
void check_placement(const std::string& resource, const VkMemoryRequirements& needs, const DeviceMemory& memory,
                     uint64_t offset, uint64_t reserved);

}  // namespace lg
