// The kernel of scene.forward_transparent: copies the lit opaque image into the output, then
// draws every alphaMode BLEND draw over it, farthest first (blend_order.h), with the G-buffer's
// material sampling and lighting.deferred's and lighting.ibl's light (shaders/forward.frag),
// depth-tested in the shader against the G-buffer's depth and writing none. Left out: shadows
// (the deferred node keeps its shadow maps to itself, so transparent surfaces are lit
// unshadowed), screen-space AO and bent normals (which describe the opaque surface behind),
// and transparent surfaces hiding or shadowing each other beyond the order of their centres.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_forward_transparent_kernel(const PlanNode& node);

}  // namespace lg
