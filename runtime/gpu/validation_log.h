// Collects what the validation layer reports (warnings and errors) through a
// VK_EXT_debug_utils messenger, so tests can fail on any message and print them all.
#pragma once

#include <vulkan/vulkan.h>

#include <mutex>
#include <string>
#include <vector>

namespace lg {

struct ValidationMessage {
  VkDebugUtilsMessageSeverityFlagBitsEXT severity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  std::string id;    // "SYNC-HAZARD-WRITE-AFTER-WRITE", "VUID-vkCmdDraw-None-02699", ...
  std::string text;  // the layer's full message
};

// Thread-safe: the layer may call from any thread that calls Vulkan.
class ValidationLog {
 public:
  void add(ValidationMessage message);
  std::vector<ValidationMessage> take();  // returns the messages so far and forgets them

  // Messenger settings that feed this log: warnings and errors of every message type.
  VkDebugUtilsMessengerCreateInfoEXT messenger_info();

 private:
  std::mutex mutex_;
  std::vector<ValidationMessage> messages_;
};

}  // namespace lg
