// Per-draw constants of passes that rasterize the scene's meshes as the G-buffer pass does
// (nodes/scene/gbuffer/shaders/draw_data.glsl, std430): world and last frame's world matrices, the
// normal matrix, and the draw's material: factors, alpha test, emission, and per texture its uv transform
// and texcoord set.
#pragma once

#include <array>
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "runtime/gpu/descriptors.h"
#include "runtime/scene/scene_view.h"

namespace lg {

// The material's textures in the order of DrawConstants::uv_transforms (and draw.glsl).
enum MaterialTexture : int {
  base_color_map,
  metallic_roughness_map,
  normal_map,
  occlusion_map,
  emissive_map,
  material_map_count
};

struct DrawConstants {
  glm::mat4 world, previous_world, normal_matrix;
  glm::vec4 base_color;
  glm::vec4 material;  // perceptual roughness, metalness, normal scale (0: no normal map), occlusion strength
  glm::vec4 alpha;     // x: alpha cutoff of MASK materials (0 otherwise); y: light_alpha_cutoff (0 for opaque)
  glm::vec4 emissive;  // rgb: emitted radiance, multiplies the emissive texture
  // Per MaterialTexture, the two rows of KHR_texture_transform's 2x3 matrix (uv' = M (u, v, 1)),
  // the texcoord set (0 or 1) in the first row's w, 1 in the second's where the texture exists.
  glm::vec4 uv_transforms[2 * material_map_count];
};

// The material's textures in MaterialTexture order.
std::array<const TextureRef*, material_map_count> material_maps(const PbrMaterial& material);

// The rows of `ref`'s uv transform as DrawConstants::uv_transforms holds them.
void uv_transform_rows(const TextureRef& ref, glm::vec4 rows[2]);

// One per SceneView::draws entry, in order.
std::vector<DrawConstants> draw_constants(const SceneView& scene);

// Each draw's constants as a uniform block bound per draw (draw.glsl's DrawBlock, the shadow
// passes' shadow_draw.glsl): lavapipe loads a storage buffer one lane at a time even where every
// lane reads the same draw (docs/lavapipe-costs.md). Draw i's block starts at i times this
// stride, a multiple of 256 bytes, the largest minUniformBufferOffsetAlignment Vulkan allows, so
// any device takes it.
inline constexpr size_t draw_block_stride = (sizeof(DrawConstants) + 255) / 256 * 256;
std::vector<std::byte> draw_blocks(const std::vector<DrawConstants>& constants);

// Draw `draw`'s block at `binding`: its range of `blocks`, a uniform buffer of draw_blocks().
DescriptorWrite draw_block(uint32_t binding, VkBuffer blocks, uint32_t draw);

}  // namespace lg
