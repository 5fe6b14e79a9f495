#include "nodes/lighting/deferred/shadow_depth_pipeline.h"

#include <cstddef>

#include "nodes/common/node_shaders.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/pipeline.h"

namespace lg {

const Pipeline& shadow_depth_pipeline(PassContext& ctx, VkFormat depth_format, bool alpha_tested) {
  GraphicsPipelineDesc desc;
  desc.name = ctx.pass().name;
  desc.vertex_shader = node_shader(alpha_tested ? "nodes/lighting/deferred/shaders/shadow_masked.vert"
                                                : "nodes/lighting/deferred/shaders/shadow.vert");
  desc.fragment_shader = node_shader(alpha_tested ? "nodes/lighting/deferred/shaders/shadow_masked.frag"
                                                  : "nodes/lighting/deferred/shaders/shadow.frag");
  desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
  if (alpha_tested) desc.bindings.push_back({1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  desc.push_constant_bytes = sizeof(ShadowDrawPush);
  // Exactly the attributes shadow_vertex.glsl reads: validation flags any other.
  desc.vertex_bindings = {{0, sizeof(GpuVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position)}};
  if (alpha_tested)
    desc.vertex_attributes.insert(desc.vertex_attributes.end(),
                                  {{2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv)},
                                   {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv1)},
                                   {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, color)}});
  desc.depth_format = depth_format;
  desc.depth_test = desc.depth_write = true;
  return ctx.pipelines().graphics(desc);
}

}  // namespace lg
