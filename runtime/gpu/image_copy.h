// Copies between whole images recorded directly (not from a plan): the executor's cached results
// carried to a new plan, a kernel keeping a result between frames.
#pragma once

#include <vulkan/vulkan.h>

namespace lg {

class Image;

// Every mip and layer of `from` into `to` (alike), each left in the layout it is read in; `to`'s
// earlier contents are discarded.
void copy_image(VkCommandBuffer cmd, const Image& from, VkImageLayout from_layout, const Image& to,
                VkImageLayout to_layout);

}  // namespace lg
