// The kernel of scene.gbuffer: rasterizes every draw of the scene into depth, normal, albedo,
// roughness/metalness and motion (layout in nodes/common/shaders/gbuffer.glsl).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_gbuffer_kernel(const PlanNode& node);

}  // namespace lg
