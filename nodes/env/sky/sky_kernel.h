// The kernel of env.sky, and the pass it records (which tests run directly): the analytic sky
// of nodes/env/sky/sky_model.h with its sun disk into every mip of a cube map, one dispatch a mip.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "nodes/env/sky/sky_model.h"
#include "runtime/exec/node_kernel.h"

namespace lg {

// `direction` turned by `radians` about +Y (counter-clockwise seen from above): env.sky's turning sun.
glm::dvec3 sun_turned(const glm::dvec3& direction, double radians);

// Records the sky into every mip of `cube` (an rgba16f cube map in GENERAL).
void record_sky(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                const SkyModel& model, Image& cube);

std::unique_ptr<NodeKernel> make_sky_kernel(const PlanNode& node);

}  // namespace lg
