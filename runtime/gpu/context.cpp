#include "runtime/gpu/context.h"

#include <cstring>

#include "runtime/gpu/device_selection.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

constexpr const char* validation_layer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  vk_check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
  std::vector<VkLayerProperties> layers(count);
  vk_check(vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

}  // namespace

Context::Context(const ContextOptions& options) {
  try {
    create_instance(options);
    DeviceChoice choice = choose_device(instance_, options.device_name);
    physical_device_ = choice.device;
    queue_family_ = choice.queue_family;
    create_device();
    load_device_functions();
    pipelines_ = std::make_unique<PipelineCache>(*this);
  } catch (...) {
    release();  // the destructor does not run for a constructor that throws
    throw;
  }
}

Context::Context(const HostDevice& host)
    : instance_(host.instance),
      physical_device_(host.physical_device),
      device_(host.device),
      queue_(host.queue),
      queue_family_(host.queue_family),
      owned_(false) {
  uint32_t family = 0;
  std::string why = device_shortcomings(physical_device_, &family);
  if (!why.empty()) throw GpuError("the host's Vulkan device cannot run Lumagraph: " + why);
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, families.data());
  const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (queue_family_ >= count || (families[queue_family_].queueFlags & needed) != needed ||
      families[queue_family_].timestampValidBits == 0)
    throw GpuError("the host's queue family " + std::to_string(queue_family_) +
                   " lacks graphics, compute or timestamps");
  timestamp_valid_bits_ = families[queue_family_].timestampValidBits;
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
  load_device_functions();
  pipelines_ = std::make_unique<PipelineCache>(*this);
}

Context::~Context() {
  pipelines_.reset();  // its pipelines belong to the device, the host's included
  release();
}

void Context::release() {
  if (!owned_) return;
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

void Context::create_instance(const ContextOptions& options) {
  auto app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = options.application_name.c_str();
  app.pEngineName = "lumagraph";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers, extensions;
  auto info = vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;

  // Synchronization validation is off by default in the layer; it finds missing barriers.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  auto features = vk_struct<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT);
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
  if (options.validation) {
    if (!has_layer(validation_layer))
      throw GpuError(std::string("validation was asked for but the ") + validation_layer +
                     " layer is not installed (Debian: vulkan-validationlayers)");
    validation_ = std::make_unique<ValidationLog>();
    messenger_info = validation_->messenger_info();
    messenger_info.pNext = &features;  // also reports on instance creation and destruction
    info.pNext = &messenger_info;
    layers.push_back(validation_layer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
  }
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  vk_check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance",
           options.validation ? "with the validation layer" : "");

  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    messenger_info.pNext = nullptr;
    vk_check(create(instance_, &messenger_info, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
  }
}

void Context::create_device() {
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &count, families.data());
  timestamp_valid_bits_ = families[queue_family_].timestampValidBits;

  const float priority = 1.0f;
  auto queue = vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue.queueFamilyIndex = queue_family_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;

  auto features13 = vk_struct<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  features13.dynamicRendering = VK_TRUE;
  features13.synchronization2 = VK_TRUE;
  features13.maintenance4 = VK_TRUE;  // glslang's SPIR-V 1.6 compute shaders declare LocalSizeId
  auto features = vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13);
  // Anisotropic filtering for material textures seen at grazing angles, where the device has it.
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physical_device_, &supported);
  features.features.samplerAnisotropy = supported.samplerAnisotropy;
  if (supported.samplerAnisotropy) max_sampler_anisotropy_ = properties_.limits.maxSamplerAnisotropy;
  // Cube arrays for gi.reflection_capture's probes, where the device has them (lavapipe does).
  features.features.imageCubeArray = supported.imageCubeArray;
  image_cube_array_ = supported.imageCubeArray == VK_TRUE;

  auto info = vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features);
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = static_cast<uint32_t>(std::size(required_device_extensions));
  info.ppEnabledExtensionNames = required_device_extensions;
  vk_check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice",
           std::string("on ") + properties_.deviceName);
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

void Context::load_device_functions() {
  cmd_push_descriptor_set =
      reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  if (!cmd_push_descriptor_set)
    throw GpuError("the device has no vkCmdPushDescriptorSetKHR: enable VK_KHR_push_descriptor on it");
}

std::vector<ValidationMessage> Context::take_validation_messages() {
  return validation_ ? validation_->take() : std::vector<ValidationMessage>{};
}

void Context::set_name(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!set_object_name_ || name.empty()) return;
  auto info = vk_struct<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  set_object_name_(device_, &info);
}

void Context::wait_idle() const {
  vk_check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle");
}

}  // namespace lg
