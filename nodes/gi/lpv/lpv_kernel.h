// gi.lpv's kernel (docs/lpv.md): three passes every frame, nothing kept between frames but the
// buffers: "rsm" draws the reflective shadow map of the main directional light; "volume" puts its
// texels into the grid as virtual point lights and occluding surfels, moves the light
// `iterations` steps, adds them up and reads the sum per pixel at resolution_scale; "upsample"
// brings that to the G-buffer's resolution.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

struct SceneView;

std::unique_ptr<NodeKernel> make_lpv_kernel(const PlanNode& node);

// The light gi.lpv carries: the first directional light that casts shadows, else the first; -1
// when there is none.
int lpv_main_light(const SceneView& scene);

}  // namespace lg
