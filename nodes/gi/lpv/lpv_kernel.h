// gi.lpv's kernel (docs/lpv.md): three passes every frame: "rsm" draws the reflective shadow map
// of the main directional light; "volume" puts its texels into the grid as virtual point lights
// and every draw's triangles as occlusion, moves the light `iterations` steps, adds them up and
// reads the sum per pixel at resolution_scale; "upsample" brings that to the G-buffer's
// resolution. The sum is kept between frames while the grid, the light, the geometry and a static
// SH stay the same (such a frame only reads it), and the sky's march while all but the light do.
#pragma once

#include <cstdint>
#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

// What the kernel tells whoever asks (tests) about the work it kept: how many frames marched the
// sky and how many built the sum (injected, propagated and stored it). A frame whose grid,
// geometry and SH are those of the last march keeps the sky's images; one whose light is the last
// build's too keeps the sum.
class LpvBuilds {
 public:
  virtual ~LpvBuilds() = default;
  virtual uint64_t sky_marches() const = 0;
  virtual uint64_t sum_builds() const = 0;
};

std::unique_ptr<NodeKernel> make_lpv_kernel(const PlanNode& node);

}  // namespace lg
