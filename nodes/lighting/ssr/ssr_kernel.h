// The kernel of lighting.ssr: the Hi-Z pyramid of the G-buffer's depth, then one reflection ray
// a pixel marched through it (shaders/hiz.comp, shaders/trace.comp say how).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_ssr_kernel(const PlanNode& node);

}  // namespace lg
