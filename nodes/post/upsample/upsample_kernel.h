// The kernel of post.upsample: joint bilateral upsampling of an image at 1/k of the G-buffer's
// resolution (shaders/upsample.comp, built on nodes/common/shaders/joint_upsample.glsl).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_upsample_kernel(const PlanNode& node);

}  // namespace lg
