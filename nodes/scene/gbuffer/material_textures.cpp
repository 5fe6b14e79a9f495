#include "nodes/scene/gbuffer/material_textures.h"

namespace lg {

void add_material_textures(GpuScene& gpu_scene, const PbrMaterial& material, std::vector<DescriptorWrite>& writes) {
  const auto maps = material_maps(material);
  for (int t = 0; t < material_map_count; ++t)
    writes.push_back(sampled_image(material_texture_bindings[t], gpu_scene.texture(maps[size_t(t)]->texture).view(),
                                   gpu_scene.sampler(maps[size_t(t)]->sampling)));
}

}  // namespace lg
