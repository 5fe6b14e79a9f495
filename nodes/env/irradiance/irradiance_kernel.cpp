#include "nodes/env/irradiance/irradiance_kernel.h"

#include <algorithm>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"

namespace lg {
namespace {

constexpr uint32_t kGroup = 8;        // both shaders' workgroup side
constexpr uint32_t kOutputBlock = 4;  // output texels a side that one invocation of irradiance.comp sums
// A light sums at most this many texels a side of a finer mip (irradiance_sources.comp): well
// inside lavapipe's 65535 loop iterations an invocation.
constexpr uint32_t kMaxBlock = 64;

struct SourcesPush {  // shaders/irradiance_sources.comp
  int32_t fine_mip;
};

class IrradianceKernel final : public NodeKernel {
 public:
  explicit IrradianceKernel(const PlanNode& node) : source_mip_(uint32_t(param_number(node, "source_mip"))) {}

  void record(PassContext& ctx) override {
    Image& env = ctx.image("in.env");
    fit_irradiance_sources(ctx.gpu(), ctx.node().id + " irradiance sources", env, source_mip_, sources_);
    record_irradiance(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, source_mip_, env, ctx.nearest_sampler(),
                      sources_, ctx.image("out.irradiance"));
  }

 private:
  uint32_t source_mip_;
  Image sources_;
};

// The finest mip of `env` whose texels under one light of a `source_face` face are at most
// kMaxBlock a side (the coarsest there is, where the chain is too short).
uint32_t fine_mip(const Image& env, uint32_t source_face) {
  uint32_t mip = 0;
  while ((env.desc().width >> mip) > kMaxBlock * source_face && mip + 1 < env.desc().mips) ++mip;
  return mip;
}

}  // namespace

uint32_t irradiance_source_face(const Image& env, uint32_t source_mip) {
  return std::clamp(env.desc().width >> std::min(source_mip, 31u), 1u, kIrradianceMaxSourceFace);
}

void fit_irradiance_sources(Context& gpu, const std::string& name, const Image& env, uint32_t source_mip,
                            Image& sources) {
  const uint32_t size = irradiance_source_face(env, source_mip);
  if (sources.handle() != VK_NULL_HANDLE && sources.desc().height == size) return;
  sources = Image::dedicated(gpu, {.name = name,
                                   .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                   .width = 2 * size,
                                   .height = size,
                                   .layers = 6,
                                   .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT});
}

void record_irradiance(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                       uint32_t source_mip, Image& env, VkSampler sampler, Image& sources, Image& irradiance) {
  const uint32_t source_size = irradiance_source_face(env, source_mip);
  const VkImageView sources_view = sources.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY});
  image_barrier(cmd, sources, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
  const Pipeline& weigh =
      pipelines.compute({name + " sources",
                         node_shader("nodes/env/irradiance/shaders/irradiance_sources.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                         sizeof(SourcesPush)});
  const DescriptorWrite source_writes[] = {sampled_image(0, env.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY}), sampler),
                                           storage_image(1, sources_view)};
  bind_pipeline(gpu, cmd, weigh, source_writes);
  push_constants(cmd, weigh, SourcesPush{int32_t(fine_mip(env, source_size))});
  vkCmdDispatch(cmd, (source_size + kGroup - 1) / kGroup, (source_size + kGroup - 1) / kGroup, 6);
  compute_to_compute_barrier(cmd);

  const Pipeline& convolve =
      pipelines.compute({name,
                         node_shader("nodes/env/irradiance/shaders/irradiance.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}});
  const DescriptorWrite writes[] = {
      sampled_image(0, sources_view, sampler, VK_IMAGE_LAYOUT_GENERAL),
      storage_image(1, irradiance.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = 0, .mip_count = 1}))};
  bind_pipeline(gpu, cmd, convolve, writes);
  const uint32_t blocks = (irradiance.desc().width + kOutputBlock - 1) / kOutputBlock;
  vkCmdDispatch(cmd, (blocks + kGroup - 1) / kGroup, (blocks + kGroup - 1) / kGroup, 6);
}

std::unique_ptr<NodeKernel> make_irradiance_kernel(const PlanNode& node) {
  return std::make_unique<IrradianceKernel>(node);
}

}  // namespace lg
