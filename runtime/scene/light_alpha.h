// Where light passes alpha-tested surfaces, the same in the shadow maps and the ray tracers.
#pragma once

#include "runtime/scene/scene_view.h"

namespace lg {

// The alpha below which light passes a surface: MASK's cutoff; 0.5 for BLEND, whose partial
// cover neither models (docs/path-tracer.md); negative for opaque materials, which always block it.
float light_alpha_cutoff(const PbrMaterial& material);

}  // namespace lg
