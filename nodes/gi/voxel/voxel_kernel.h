// gi.voxel's kernel (docs/voxel.md): three passes every frame, nothing kept between frames but the
// buffer of sums and the chain's three 3D images: "shadow" draws the depth of the main
// directional light; "volume" voxelizes every draw, injects the light, builds the mip chain and
// traces six cones per pixel at resolution_scale; "upsample" brings the irradiance and the
// ambient occlusion to the G-buffer's resolution.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_voxel_kernel(const PlanNode& node);

}  // namespace lg
