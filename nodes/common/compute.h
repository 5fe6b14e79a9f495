// Running a kernel's compute pass: the pipeline of one of the node's shaders, its descriptors
// and push constants, and one invocation per texel of the target.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/descriptors.h"

namespace lg {

// Shaders declare local_size_x = local_size_y = kTileSize (or pass their own `tile`) and
// return for texels outside the target, so any size dispatches.
inline constexpr uint32_t kTileSize = 8;

inline void dispatch_texels(VkCommandBuffer cmd, uint32_t width, uint32_t height, uint32_t tile = kTileSize) {
  vkCmdDispatch(cmd, (width + tile - 1) / tile, (height + tile - 1) / tile, 1);
}

// Between dispatches of one pass that read what the one before wrote (the levels of a mip
// chain): the plan's barriers order passes, not the dispatches inside one.
void compute_to_compute_barrier(VkCommandBuffer cmd);

// The pipeline of `shader` (a path under nodes/, see node_shaders.h) takes its bindings from
// `writes` and its specialization constants from `constants` (ComputePipelineDesc::constants);
// the pass's name labels it in validation messages.
void dispatch_compute(PassContext& ctx, std::string_view shader, std::span<const DescriptorWrite> writes,
                      uint32_t width, uint32_t height, std::span<const std::byte> push = {}, uint32_t tile = kTileSize,
                      std::span<const uint32_t> constants = {});

}  // namespace lg
