// The kernel of occlusion.gtao: linear depth with min mips, horizon search with bent normals,
// then the depth-aware denoiser with temporal accumulation (shaders/*.comp say how).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_gtao_kernel(const PlanNode& node);

}  // namespace lg
