// gi.prt's kernel: the environment's SH turned by this frame's rotation and dotted with every
// baked vertex's transfer (a compute dispatch), then every draw rasterized with its vertices'
// irradiance interpolated, as the G-buffer pass draws it; one pass, "shade" (docs/prt.md).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_prt_kernel(const PlanNode& node);

}  // namespace lg
