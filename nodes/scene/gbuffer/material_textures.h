// The material's textures as the shaders that sample a draw's material bind them
// (nodes/scene/gbuffer/shaders/gbuffer_material.glsl): the G-buffer's and scene.forward_transparent's.
#pragma once

#include <cstdint>
#include <vector>

#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/descriptors.h"

namespace lg {

// Per MaterialTexture. The emissive texture came last, when forward.frag already bound the
// environment and the lights at 6 to 20.
constexpr uint32_t material_texture_bindings[material_map_count] = {2, 3, 4, 5, 21};

// The material's textures (a white texel where it has none) with their samplers.
void add_material_textures(GpuScene& gpu_scene, const PbrMaterial& material, std::vector<DescriptorWrite>& writes);

}  // namespace lg
