#include "nodes/scene/forward_transparent/forward_bindings.h"

#include "nodes/common/node_shaders.h"
#include "runtime/exec/gpu_scene.h"

namespace lg {
namespace {

// forward_shading.glsl's bindings: constants 0, the light lists (11 to 13, 16 to 18), the local
// shadow views 15, settings 20 and the LTC table 22 uniform; draws 1 and SH 6 storage buffers;
// the rest sampled images (the material's textures at material_texture_bindings among them).
VkDescriptorType binding_type(uint32_t b) {
  if (b == 0 || (b >= 11 && b <= 13) || b == 15 || (b >= 16 && b <= 18) || b == 20 || b == 22)
    return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  if (b == 1 || b == 6)
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
}

constexpr uint32_t kLastBinding = 22;

}  // namespace

std::vector<DescriptorWrite> forward_writes(const LightBuffers& lights, VkBuffer draws, VkBuffer settings,
                                            const ForwardResources& r) {
  std::vector<DescriptorWrite> writes;
  lights.add_constants(writes);
  writes.push_back(storage_buffer(1, draws));
  writes.push_back(storage_buffer(6, r.sh));
  writes.push_back(sampled_image(7, r.irradiance, r.linear));
  writes.push_back(sampled_image(8, r.specular, r.linear));
  writes.push_back(sampled_image(9, r.brdf_lut, r.linear));
  writes.push_back(sampled_image(10, r.placeholder_2d, r.nearest));
  writes.push_back(sampled_image(14, r.placeholder_2d, r.nearest));
  lights.add_direct_lists(writes);
  lights.add_shadow_views(writes);
  lights.add_area_lists(writes);
  writes.push_back(sampled_image(19, r.placeholder_2d, r.nearest));
  writes.push_back(uniform_buffer(20, settings));
  return writes;
}

GraphicsPipelineDesc forward_pipeline_desc(std::string name, std::span<const uint32_t> fragment, VkFormat color,
                                           bool double_sided) {
  GraphicsPipelineDesc desc;
  desc.name = std::move(name);
  desc.vertex_shader = node_shader("nodes/scene/gbuffer/shaders/gbuffer.vert");
  desc.fragment_shader = fragment;
  for (uint32_t b = 0; b <= kLastBinding; ++b) desc.bindings.push_back({b, binding_type(b)});
  desc.push_constant_bytes = sizeof(uint32_t);
  use_gpu_vertices(desc, true);
  desc.cull = double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
  desc.color_formats = {color};
  return desc;
}

}  // namespace lg
