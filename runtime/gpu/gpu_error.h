// Errors of the Vulkan layer. Every failed Vulkan call and every misuse the layer detects
// (an unknown format, a placement too small for its resource, a submit that times out) throws a
// GpuError whose message names the call or the resource, so no failure is silent.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace lg {

class GpuError : public std::runtime_error {
 public:
  explicit GpuError(const std::string& message, VkResult result = VK_SUCCESS)
      : std::runtime_error(message), result_(result) {}
  // The Vulkan result that failed, or VK_SUCCESS for errors the layer found itself.
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

// "VK_ERROR_OUT_OF_DEVICE_MEMORY"; unknown codes print as their number.
std::string vk_result_name(VkResult result);

// Throws GpuError("<call> failed: <result>[ <context>]") when `result` is an error code
// (negative); success and status codes (VK_TIMEOUT, VK_NOT_READY, ...) return normally.
// vk_check(vkAllocateMemory(...), "vkAllocateMemory", "while allocating block 0 (113.6 MiB)")
void vk_check(VkResult result, std::string_view call, std::string_view context = {});

}  // namespace lg
