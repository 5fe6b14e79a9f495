// draw_constants(): the scene's draws as draw_data.glsl reads them.
#include "nodes/scene/gbuffer/draw_constants.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "runtime/scene/light_alpha.h"

namespace lg {

std::array<const TextureRef*, material_map_count> material_maps(const PbrMaterial& m) {
  return {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture, &m.occlusion_texture,
          &m.emissive_texture};
}

void uv_transform_rows(const TextureRef& ref, glm::vec4 rows[2]) {
  // KHR_texture_transform: T(offset) R(rotation) S(scale), R = [cos sin; -sin cos].
  const float c = std::cos(ref.rotation), s = std::sin(ref.rotation);
  rows[0] = {c * ref.scale.x, s * ref.scale.y, ref.offset.x, float(ref.texcoord)};
  rows[1] = {-s * ref.scale.x, c * ref.scale.y, ref.offset.y, ref.texture >= 0 ? 1.0f : 0.0f};
}

std::vector<DrawConstants> draw_constants(const SceneView& scene) {
  std::vector<DrawConstants> out(scene.draws.size());
  for (size_t i = 0; i < scene.draws.size(); ++i) {
    const DrawItem& d = scene.draws[i];
    const PbrMaterial& m = scene.material_of(d);
    DrawConstants& c = out[i];
    c.world = d.world;
    c.previous_world = d.previous_world;
    c.normal_matrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(d.world))));
    c.base_color = m.base_color;
    c.material = {m.roughness, m.metalness, m.normal_texture.texture >= 0 ? m.normal_scale : 0.0f,
                  m.occlusion_strength};
    c.alpha = {m.alpha_mode == AlphaMode::mask ? m.alpha_cutoff : 0.0f, std::max(light_alpha_cutoff(m), 0.0f), 0.0f,
               0.0f};
    c.emissive = glm::vec4(m.emissive, 0.0f);
    const auto maps = material_maps(m);
    for (int t = 0; t < material_map_count; ++t) uv_transform_rows(*maps[size_t(t)], &c.uv_transforms[2 * t]);
  }
  return out;
}

std::vector<std::byte> draw_blocks(const std::vector<DrawConstants>& constants) {
  std::vector<std::byte> bytes(std::max<size_t>(constants.size(), 1) * draw_block_stride);
  for (size_t i = 0; i < constants.size(); ++i)
    std::memcpy(bytes.data() + i * draw_block_stride, &constants[i], sizeof(DrawConstants));
  return bytes;
}

DescriptorWrite draw_block(uint32_t binding, VkBuffer blocks, uint32_t draw) {
  return uniform_buffer(binding, blocks, draw * draw_block_stride, sizeof(DrawConstants));
}

}  // namespace lg
