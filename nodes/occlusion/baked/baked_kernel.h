// The kernel of occlusion.baked: draws the scene's offline bakes (vertex and texel) for the
// frame's camera and writes the same ao and bent_normals as occlusion.gtao.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_baked_kernel(const PlanNode& node);

}  // namespace lg
