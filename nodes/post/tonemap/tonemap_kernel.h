// The kernel of post.tonemap: exposure, tone curve and sRGB encoding in one compute pass.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_tonemap_kernel(const PlanNode& node);

}  // namespace lg
