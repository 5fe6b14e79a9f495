// The kernel of post.bilateral: a joint bilateral filter of an HDR image guided by the
// G-buffer's depth and normals, as the full 2D kernel (shaders/bilateral_full.comp) or as rows
// then columns (shaders/bilateral_line.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_bilateral_kernel(const PlanNode& node);

}  // namespace lg
