// The kernel of gi.irradiance_volume: bakes the scene's probe volumes on the CPU when what they
// depend on changes (probe_bake_key.h), keeps them on the device, and looks them up per G-buffer
// pixel (shaders/irradiance_volume.comp).
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_irradiance_volume_kernel(const PlanNode& node);

}  // namespace lg
