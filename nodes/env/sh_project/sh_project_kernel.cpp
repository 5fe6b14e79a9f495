#include "nodes/env/sh_project/sh_project_kernel.h"

#include <stdexcept>

#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

constexpr uint32_t kBlockTexels = 64 * 32;  // nodes/env/sh_project/shaders/sh_project.comp
constexpr uint64_t kBlockSums = 25;         // vec4s per block: room for every coefficient up to band 4

struct ReducePush {  // nodes/env/sh_project/shaders/sh_reduce.comp
  float band_factor[8];
  int32_t order;
  int32_t blocks;
};

// Blocks of one face.
uint32_t face_blocks(const Image& env) {
  const uint64_t size = env.desc().width >> sh_project_mip(env);
  return uint32_t((size * size + kBlockTexels - 1) / kBlockTexels);
}

void partials_written_barrier(VkCommandBuffer cmd, const Buffer& partials) {
  auto b = vk_struct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
  b.srcStageMask = b.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  b.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = partials.handle();
  b.size = VK_WHOLE_SIZE;
  auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

class ShProjectKernel final : public NodeKernel {
 public:
  explicit ShProjectKernel(const PlanNode& node)
      : settings_(sh_project_settings(int(param_number(node, "order")),
                                      sh_window_from_name(param_string(node, "window")),
                                      param_number(node, "window_target"), param_bool(node, "convolve_cosine"))) {}

  void record(PassContext& ctx) override {
    Image& env = ctx.image("in.env");
    const uint64_t bytes = sh_partials_bytes(env);
    if (partials_.size() < bytes)
      partials_ = Buffer::dedicated(ctx.gpu(), {.name = ctx.node().id + " SH partial sums", .size = bytes});
    record_sh_project(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, settings_, env, ctx.nearest_sampler(),
                      partials_, ctx.buffer("out.sh"));
  }

 private:
  ShProjectSettings settings_;
  Buffer partials_;
};

}  // namespace

ShProjectSettings sh_project_settings(int order, ShWindow window, double window_target, bool convolve_cosine) {
  if (order < 0 || order > kMaxShOrder) throw std::invalid_argument("SH order must be 0 to 4");
  ShProjectSettings s{order, sh_window(window, order, window_target, convolve_cosine)};
  if (convolve_cosine)
    for (int l = 0; l <= order; ++l) s.band_factors[l] *= cosine_lobe_band(l);
  return s;
}

uint32_t sh_project_mip(const Image& env) {
  uint32_t mip = 0;
  while ((env.desc().width >> mip) > kShProjectMaxFace && mip + 1 < env.desc().mips) ++mip;
  if ((env.desc().width >> mip) > kShProjectMaxFace)
    throw std::invalid_argument("SH projection of '" + env.desc().name + "': an environment over " +
                                std::to_string(kShProjectMaxFace) + " texels a face needs its mips");
  return mip;
}

uint64_t sh_partials_bytes(const Image& env) {
  return uint64_t(face_blocks(env)) * 6 * kBlockSums * 16;
}

void record_sh_project(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                       const ShProjectSettings& settings, Image& env, VkSampler sampler, const Buffer& partials,
                       const Buffer& coefficients) {
  const uint32_t blocks = face_blocks(env);
  const VkImageView faces =
      env.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = sh_project_mip(env), .mip_count = 1});
  const DescriptorWrite block_writes[] = {sampled_image(0, faces, sampler), storage_buffer(1, partials.handle())};
  const Pipeline& project =
      pipelines.compute({name + " blocks",
                         node_shader("nodes/env/sh_project/shaders/sh_project.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                         0,
                         {uint32_t(sh_count(settings.order))}});  // sh_project.comp's `count`
  bind_pipeline(gpu, cmd, project, block_writes);
  vkCmdDispatch(cmd, blocks, 6, 1);
  partials_written_barrier(cmd, partials);

  ReducePush push{};
  for (int l = 0; l <= settings.order; ++l) push.band_factor[l] = float(settings.band_factors[l]);
  push.order = settings.order;
  push.blocks = int32_t(blocks * 6);
  const DescriptorWrite sum_writes[] = {storage_buffer(0, partials.handle()), storage_buffer(1, coefficients.handle())};
  const Pipeline& reduce =
      pipelines.compute({name + " sum",
                         node_shader("nodes/env/sh_project/shaders/sh_reduce.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                         sizeof(ReducePush)});
  bind_pipeline(gpu, cmd, reduce, sum_writes);
  push_constants(cmd, reduce, push);
  vkCmdDispatch(cmd, 1, 1, 1);
}

std::unique_ptr<NodeKernel> make_sh_project_kernel(const PlanNode& node) {
  return std::make_unique<ShProjectKernel>(node);
}

}  // namespace lg
