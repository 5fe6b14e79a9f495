// The kernel of scene.gbuffer: rasterizes every draw of the scene that the camera's frustum
// touches (runtime/scene/frustum.h) into depth, normal, albedo,
// roughness/metalness and motion (layout in nodes/common/shaders/gbuffer.glsl), with the glTF
// metal-rough material (shaders/gbuffer_surface.glsl): its base colour, metallic-roughness,
// normal and occlusion textures, vertex colours, the MASK alpha test (a pipeline variant with
// the discard, so opaque draws keep early depth testing) and double-sided materials drawn
// without culling; draws without textures or vertex colours take a plain variant that reads
// the factors only. BLEND materials are skipped: scene.forward_transparent draws them over the
// lit image. The emissive texture and factor are not drawn: the G-buffer has no channel for them.
#pragma once

#include <memory>

#include "runtime/exec/node_kernel.h"

namespace lg {

std::unique_ptr<NodeKernel> make_gbuffer_kernel(const PlanNode& node);

}  // namespace lg
