// The kernel of scene.gbuffer: rasterizes every draw of the scene that the camera's frustum
// touches (runtime/scene/frustum.h) into depth, normal, albedo,
// roughness/metalness, motion and emitted radiance (layout in nodes/common/shaders/gbuffer.glsl),
// with the glTF metal-rough material (shaders/gbuffer_surface.glsl): its base colour,
// metallic-roughness, normal, occlusion and emissive textures, vertex colours, the MASK alpha test (a pipeline variant
// with the discard, so opaque draws keep early depth testing) and double-sided materials drawn without culling; draws
// without textures or vertex colours take a plain variant that reads the factors only. BLEND materials are skipped:
// scene.forward_transparent draws them over the lit image.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_gbuffer_kernel(const PlanNode& node);

}  // namespace lg
