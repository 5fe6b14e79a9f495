// gi.lpv's kernel (docs/lpv.md): three passes every frame, nothing kept between frames but the
// buffers: "rsm" draws the reflective shadow map of the main directional light; "volume" puts its
// texels into the grid as virtual point lights and every draw's triangles as occlusion, moves the light
// `iterations` steps, adds them up and reads the sum per pixel at resolution_scale; "upsample"
// brings that to the G-buffer's resolution.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_lpv_kernel(const PlanNode& node);

}  // namespace lg
