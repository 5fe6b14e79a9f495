// The kernel of occlusion.gtao: device depth with averaged mips, horizon search with bent normals,
// then the depth-aware denoiser with temporal accumulation, both on the grid of resolution_scale,
// and below 1 a joint bilateral upsample to full resolution (shaders/*.comp say how).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_gtao_kernel(const PlanNode& node);

}  // namespace lg
