#include "nodes/common/compute.h"

#include "nodes/common/node_shaders.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/pipeline.h"

namespace lg {

void compute_to_compute_barrier(VkCommandBuffer cmd) {
  memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                 {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                                                              VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}

void dispatch_compute(PassContext& ctx, std::string_view shader, std::span<const DescriptorWrite> writes,
                      uint32_t width, uint32_t height, std::span<const std::byte> push, uint32_t tile,
                      std::span<const uint32_t> constants) {
  ComputePipelineDesc desc;
  desc.constants.assign(constants.begin(), constants.end());
  desc.name = ctx.pass().name;
  desc.shader = node_shader(shader);
  for (const DescriptorWrite& w : writes) desc.bindings.push_back({w.binding, w.type});
  desc.push_constant_bytes = static_cast<uint32_t>(push.size());
  const Pipeline& pipeline = ctx.pipelines().compute(desc);
  bind_pipeline(ctx.gpu(), ctx.cmd(), pipeline, writes);
  if (!push.empty()) push_constants(ctx.cmd(), pipeline, push.data(), desc.push_constant_bytes);
  dispatch_texels(ctx.cmd(), width, height, tile);
}

}  // namespace lg
