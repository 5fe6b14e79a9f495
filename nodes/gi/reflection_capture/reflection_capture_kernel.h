// The kernel of gi.reflection_capture (schema.json, docs/reflection-probes.md).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_reflection_capture_kernel(const PlanNode& node);

}  // namespace lg
