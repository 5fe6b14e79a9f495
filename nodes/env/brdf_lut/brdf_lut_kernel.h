// The kernel of env.brdf_lut, and the pass it records (which tests run directly): the split-sum
// DFG table (layout in nodes/env/brdf_lut/shaders/dfg.comp and docs/env-conventions.md).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>

#include "runtime/exec/node_kernel.h"

namespace lg {

// lavapipe ends an invocation's loops after 65535 iterations in all: more samples are clamped.
inline constexpr uint32_t kMaxLutSamples = 32768;

// Records the table into `lut` (rg16f, in GENERAL).
void record_brdf_lut(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                     uint32_t samples, Image& lut);

std::unique_ptr<NodeKernel> make_brdf_lut_kernel(const PlanNode& node);

}  // namespace lg
