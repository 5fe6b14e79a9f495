#include "runtime/gpu/device_selection.h"

#include <cstring>
#include <vector>

#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

bool has_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vk_check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr), "vkEnumerateDeviceExtensionProperties");
  std::vector<VkExtensionProperties> extensions(count);
  vk_check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()),
           "vkEnumerateDeviceExtensionProperties");
  for (const auto& e : extensions)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

}  // namespace

std::string device_shortcomings(VkPhysicalDevice device, uint32_t* queue_family) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);
  if (properties.apiVersion < VK_API_VERSION_1_3) return "it supports Vulkan 1." + std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + ", not 1.3";

  auto features13 = vk_struct<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  auto features = vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13);
  vkGetPhysicalDeviceFeatures2(device, &features);
  std::string missing;
  auto lacks = [&](const std::string& what) { missing += (missing.empty() ? "it lacks " : ", ") + what; };
  if (!features13.dynamicRendering) lacks("dynamicRendering");
  if (!features13.synchronization2) lacks("synchronization2");
  if (!features13.maintenance4) lacks("maintenance4");
  for (const char* extension : required_device_extensions)
    if (!has_extension(device, extension)) lacks(extension);

  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  bool found = false;
  for (uint32_t f = 0; f < count && !found; ++f) {
    if ((families[f].queueFlags & needed) == needed && families[f].timestampValidBits > 0) {
      found = true;
      if (queue_family) *queue_family = f;
    }
  }
  if (!found) lacks("a queue family with graphics, compute and timestamps");
  return missing;
}

DeviceChoice choose_device(VkInstance instance, std::string_view name) {
  uint32_t count = 0;
  vk_check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  vk_check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");

  DeviceChoice best;
  int best_rank = 1 << 30;
  std::string report;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    std::string device_name = properties.deviceName;
    std::string why;
    uint32_t family = 0;
    if (!name.empty() && device_name.find(name) == std::string::npos) why = "its name does not contain '" + std::string(name) + "'";
    else why = device_shortcomings(device, &family);
    if (why.empty() && type_rank(properties.deviceType) < best_rank) {
      best = {device, family};
      best_rank = type_rank(properties.deviceType);
    }
    report += "\n  " + device_name + (why.empty() ? ": suitable" : ": " + why);
  }
  if (best.device == VK_NULL_HANDLE) {
    if (devices.empty()) throw GpuError("no Vulkan device found (is a Vulkan driver installed? for the CPU driver: mesa-vulkan-drivers)");
    throw GpuError("no suitable Vulkan device" + (name.empty() ? std::string() : " named like '" + std::string(name) + "'") + ":" + report);
  }
  return best;
}

}  // namespace lg
