// The kernel of occlusion.bake: bakes the scene's visibility grid on the CPU when the geometry
// changes (meshes, or draws added, removed or moved) and looks it up per pixel
// (shaders/volume_lookup.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_bake_kernel(const PlanNode& node);

}  // namespace lg
