// gi.lpv's kernel (docs/lpv.md): three passes every frame, nothing kept between frames but the
// buffers and the sky's march (redone when the grid, the geometry or the SH changed): "rsm" draws
// the reflective shadow map of the main directional light; "volume" puts its texels into the grid
// as virtual point lights and every draw's triangles as occlusion, moves the light `iterations`
// steps, adds them up and reads the sum per pixel at resolution_scale; "upsample" brings that to
// the G-buffer's resolution.
#pragma once

#include <cstdint>
#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

// What the kernel tells whoever asks (tests) about the sky's march: how many frames marched it.
// A frame whose grid, geometry and SH are those of the last march keeps its images instead.
class LpvSkyMarches {
 public:
  virtual ~LpvSkyMarches() = default;
  virtual uint64_t sky_marches() const = 0;
};

std::unique_ptr<NodeKernel> make_lpv_kernel(const PlanNode& node);

}  // namespace lg
