// The kernel of post.exposure: a histogram pass into the node's own 256-bin buffer, then a
// one-invocation pass that meters it and adapts from the history (exposure_metering.h).
#pragma once

#include <memory>

#include "nodes/post/exposure/exposure_metering.h"
#include "runtime/exec/node_kernel.h"

namespace lg {

// The node's params; throws std::invalid_argument naming the node when they contradict.
ExposureSettings exposure_settings(const PlanNode& node);

std::unique_ptr<NodeKernel> make_exposure_kernel(const PlanNode& node);

}  // namespace lg
