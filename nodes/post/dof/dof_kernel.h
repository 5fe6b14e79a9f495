// The kernel of post.dof: the thin lens's circle of confusion from depth, a half-resolution
// gather, and a composite (shaders/*.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_dof_kernel(const PlanNode& node);

}  // namespace lg
