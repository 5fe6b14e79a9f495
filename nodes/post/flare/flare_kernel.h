// The kernel of post.flare: the bright part averaged onto a low-res grid, ghosts, halo and
// streaks of it there, a guard that holds their energy to the bright part's, and a composite
// that adds them to the image (shaders/*.comp; the model: flare_model.h).
#pragma once

#include <memory>

#include "nodes/post/flare/flare_model.h"
#include "runtime/exec/node_kernel.h"

namespace lg {

// The node's params as the model's settings.
FlareSettings flare_settings(const PlanNode& node);

std::unique_ptr<NodeKernel> make_flare_kernel(const PlanNode& node);

}  // namespace lg
