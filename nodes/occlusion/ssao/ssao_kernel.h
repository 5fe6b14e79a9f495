// The kernel of occlusion.ssao: hemisphere sampling against the depth buffer, then a
// depth-aware blur (shaders/*.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_ssao_kernel(const PlanNode& node);

}  // namespace lg
