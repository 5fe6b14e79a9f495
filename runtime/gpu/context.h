// The Vulkan 1.3 instance, device and queue Lumagraph runs on: either created here (the first
// suitable device, or one picked by name) or adopted from a host engine, which keeps owning it.
// Requires dynamic rendering, synchronization2, maintenance4 (SPIR-V 1.6 shaders), timestamps
// and VK_KHR_push_descriptor. With
// validation on, the Khronos layer runs with synchronization validation and its warnings and
// errors collect in a log that tests check.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "runtime/gpu/validation_log.h"

namespace lg {

class PipelineCache;

struct ContextOptions {
  bool validation = false;    // Khronos validation layer + synchronization validation
  std::string device_name{};  // a substring of the device's name; empty: the first suitable
  std::string application_name = "lumagraph";
};

// A device the host engine created and keeps owning. It must be Vulkan 1.3 with
// dynamicRendering, synchronization2, maintenance4 and VK_KHR_push_descriptor enabled; the
// queue's family must do graphics, compute and timestamps.
struct HostDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  explicit Context(const HostDevice& host);  // adopts; never destroys the host's objects
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  // Submissions to the queue must not overlap from several threads (Vulkan requires it).
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  bool owns_device() const { return owned_; }

  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }
  std::string_view device_name() const { return properties_.deviceName; }
  double timestamp_period_ns() const { return properties_.limits.timestampPeriod; }
  uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
  // The device's anisotropic filtering limit where this context enabled samplerAnisotropy (on
  // its own device, when the device has it); 1 otherwise, a host's device included.
  float max_sampler_anisotropy() const { return max_sampler_anisotropy_; }
  // Whether this context enabled imageCubeArray (its own device, when the device has it; a
  // host's device is not asked).
  bool image_cube_array() const { return image_cube_array_; }

  // Bytes of device memory allocated through Lumagraph and not yet freed.
  uint64_t device_memory_used() const { return memory_used_; }

  bool validation_enabled() const { return validation_ != nullptr; }
  // Validation warnings and errors since the last call; empty without validation.
  std::vector<ValidationMessage> take_validation_messages();

  // Names an object in validation messages and debuggers; does nothing without validation.
  void set_name(VkObjectType type, uint64_t handle, const std::string& name) const;
  template <typename Handle>
  void set_name(VkObjectType type, Handle handle, const std::string& name) const {
    set_name(type, reinterpret_cast<uint64_t>(handle), name);
  }

  void wait_idle() const;

  // The pipelines of this device, shared by every executor on it: a recompile, a resize or a hot
  // reload reuses those the last plan made. They live as long as the context.
  PipelineCache& pipelines() const { return *pipelines_; }

  // Device-level entry points of extensions.
  PFN_vkCmdPushDescriptorSetKHR cmd_push_descriptor_set = nullptr;

 private:
  friend class DeviceMemory;  // keeps memory_used_
  void create_instance(const ContextOptions& options);
  void create_device();
  void load_device_functions();
  void release();  // destroys what this context created

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  uint32_t timestamp_valid_bits_ = 64;
  float max_sampler_anisotropy_ = 1.0f;
  bool image_cube_array_ = false;
  bool owned_ = true;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  std::unique_ptr<ValidationLog> validation_;  // stable address: the messenger points at it
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
  std::atomic<uint64_t> memory_used_{0};
  std::unique_ptr<PipelineCache> pipelines_;  // made last, destroyed before the device
};

}  // namespace lg
