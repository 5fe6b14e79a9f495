// Picks the physical device and queue family Lumagraph runs on, and says in words why a device
// does not qualify (Vulkan 1.3, dynamic rendering, synchronization2, maintenance4, push
// descriptors, a queue family with graphics, compute and timestamps).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace lg {

inline constexpr const char* required_device_extensions[] = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};

struct DeviceChoice {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
};

// Empty when `device` qualifies; otherwise what it lacks. `queue_family`, when not null, gets
// the first family with graphics, compute and timestamps.
std::string device_shortcomings(VkPhysicalDevice device, uint32_t* queue_family);

// The first qualifying device whose name contains `name` (any, when empty), preferring
// discrete over integrated over other GPUs over CPU devices. Throws GpuError listing every
// device and why it was passed over.
DeviceChoice choose_device(VkInstance instance, std::string_view name);

}  // namespace lg
