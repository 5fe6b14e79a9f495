#include "runtime/gpu/memory.h"

#include <cstdio>
#include <utility>

#include "graph/fault_injection.h"
#include "graph/plan_format.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

std::string bytes_text(uint64_t bytes) {
  return format_bytes(bytes) + (bytes >= 1024 ? " (" + std::to_string(bytes) + " bytes)" : "");
}

std::string hex(uint32_t bits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%x", bits);
  return buf;
}

}  // namespace

uint32_t find_memory_type(const Context& context, uint32_t type_bits, MemoryUse use, const std::string& what) {
  const VkPhysicalDeviceMemoryProperties& props = context.memory_properties();
  const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  auto find = [&](VkMemoryPropertyFlags wanted) -> int {
    for (uint32_t t = 0; t < props.memoryTypeCount; ++t)
      if ((type_bits >> t & 1) && (props.memoryTypes[t].propertyFlags & wanted) == wanted) return static_cast<int>(t);
    return -1;
  };
  int type = -1;
  switch (use) {
    case MemoryUse::device_local: type = find(VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT); break;
    case MemoryUse::upload: type = find(host); break;
    case MemoryUse::readback:
      type = find(host | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
      if (type < 0) type = find(host);
      break;
  }
  if (type < 0)
    throw GpuError("no memory type for " + what + " among the allowed types " + hex(type_bits) + " with the " +
                   (use == MemoryUse::device_local ? "device-local" : "host-visible, coherent") + " property");
  return static_cast<uint32_t>(type);
}

DeviceMemory::DeviceMemory(Context& context, uint64_t size, uint32_t type_bits, MemoryUse use, std::string name)
    : context_(&context), size_(size), name_(std::move(name)) {
  if (size == 0) return;
  type_index_ = find_memory_type(context, type_bits, use, name_);
  auto info = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  info.allocationSize = size;
  info.memoryTypeIndex = type_index_;
  const VkResult allocated = inject_fault(FaultSite::device_allocation)
                                 ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                 : vkAllocateMemory(context.device(), &info, nullptr, &memory_);
  vk_check(allocated, "vkAllocateMemory",
           "while allocating " + name_ + " (" + format_bytes(size) + ")");
  context.memory_used_ += size;
  context.set_name(VK_OBJECT_TYPE_DEVICE_MEMORY, memory_, name_);
  if (use != MemoryUse::device_local) {
    void* data = nullptr;
    VkResult r = vkMapMemory(context.device(), memory_, 0, VK_WHOLE_SIZE, 0, &data);
    if (r != VK_SUCCESS) release();
    vk_check(r, "vkMapMemory", "while mapping " + name_);
    mapped_ = static_cast<std::byte*>(data);
  }
}

DeviceMemory::~DeviceMemory() { release(); }

DeviceMemory::DeviceMemory(DeviceMemory&& other) noexcept { *this = std::move(other); }

DeviceMemory& DeviceMemory::operator=(DeviceMemory&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    type_index_ = other.type_index_;
    name_ = std::move(other.name_);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void DeviceMemory::release() {
  if (!memory_) return;
  vkFreeMemory(context_->device(), memory_, nullptr);  // unmaps implicitly
  context_->memory_used_ -= size_;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

void check_placement(const std::string& resource, const VkMemoryRequirements& needs, const DeviceMemory& memory,
                     uint64_t offset, uint64_t reserved) {
  const std::string where = "its placement at offset " + std::to_string(offset) + " of " + memory.name();
  if (!memory.handle())
    throw GpuError("'" + resource + "' is placed in " + memory.name() + ", which holds no memory (size 0)");
  if (needs.size > reserved)
    throw GpuError("'" + resource + "' needs " + bytes_text(needs.size) + " of device memory but " + where +
                   " reserves only " + bytes_text(reserved));
  if (offset % needs.alignment != 0)
    throw GpuError("'" + resource + "' must start at a multiple of " + std::to_string(needs.alignment) + " bytes, but " +
                   where + " is not");
  if (offset + needs.size > memory.size())
    throw GpuError("'" + resource + "' (" + bytes_text(needs.size) + ") at " + where + " runs past its end (" +
                   bytes_text(memory.size()) + ")");
  if (!(needs.memoryTypeBits >> memory.type_index() & 1))
    throw GpuError("'" + resource + "' accepts memory types " + hex(needs.memoryTypeBits) + ", but " + memory.name() +
                   " has type " + std::to_string(memory.type_index()));
}

}  // namespace lg
