// The kernel of post.bloom: a half-resolution mip chain blurred on the way down and summed on
// the way up, then composited so the frame's energy is unchanged (shaders/*.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_bloom_kernel(const PlanNode& node);

}  // namespace lg
