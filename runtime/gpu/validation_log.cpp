#include "runtime/gpu/validation_log.h"

#include <utility>

#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  ValidationMessage m;
  m.severity = severity;
  if (data->pMessageIdName) m.id = data->pMessageIdName;
  if (data->pMessage) m.text = data->pMessage;
  static_cast<ValidationLog*>(user)->add(std::move(m));
  return VK_FALSE;  // the call that triggered it goes on, as the spec requires
}

}  // namespace

void ValidationLog::add(ValidationMessage message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

std::vector<ValidationMessage> ValidationLog::take() {
  std::lock_guard lock(mutex_);
  return std::exchange(messages_, {});
}

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messenger_info() {
  auto info = vk_struct<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = on_message;
  info.pUserData = this;
  return info;
}

}  // namespace lg
