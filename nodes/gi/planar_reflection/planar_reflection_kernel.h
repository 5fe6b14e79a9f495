// The kernel of gi.planar_reflection (schema.json, docs/planar-reflections.md).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_planar_reflection_kernel(const PlanNode& node);

}  // namespace lg
