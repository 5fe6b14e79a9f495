// Vulkan structures zeroed apart from their sType and pNext. Brace-initialising only the
// sType trips -Wmissing-field-initializers (part of -Wextra), even with designators.
#pragma once

#include <vulkan/vulkan.h>

namespace lg {

template <typename T>
T vk_struct(VkStructureType type, void* next = nullptr) {
  T value{};
  value.sType = type;
  value.pNext = next;
  return value;
}

}  // namespace lg
