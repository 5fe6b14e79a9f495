// Small helpers for kernels' compute passes: dispatching one invocation per texel.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace lg {

// Shaders declare local_size_x = local_size_y = kTileSize and return for texels outside the
// image, so any size dispatches.
inline constexpr uint32_t kTileSize = 8;

inline void dispatch_texels(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
  vkCmdDispatch(cmd, (width + kTileSize - 1) / kTileSize, (height + kTileSize - 1) / kTileSize, 1);
}

}  // namespace lg
