// The kernel of lighting.deferred: the shadow map of the first shadow-casting directional
// light, directional and point lights, then sphere, tube and rectangle area lights.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_deferred_kernel(const PlanNode& node);

}  // namespace lg
