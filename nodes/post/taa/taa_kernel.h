// The kernel of post.taa: temporal anti-aliasing (shaders/resolve.comp) and its optional
// sharpening (shaders/sharpen.comp). The camera jitter it needs is applied by the executor for
// every pass of the frame (the schema's "camera_jitter", runtime/scene/camera_jitter.h).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_taa_kernel(const PlanNode& node);

}  // namespace lg
