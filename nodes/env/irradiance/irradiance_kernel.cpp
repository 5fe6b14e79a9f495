#include "nodes/env/irradiance/irradiance_kernel.h"

#include <algorithm>

#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"

namespace lg {
namespace {

constexpr uint32_t kGroup = 8;

class IrradianceKernel final : public NodeKernel {
 public:
  explicit IrradianceKernel(const PlanNode& node) : source_mip_(uint32_t(param_number(node, "source_mip"))) {}

  void record(PassContext& ctx) override {
    record_irradiance(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, source_mip_, ctx.image("in.env"),
                      ctx.nearest_sampler(), ctx.image("out.irradiance"));
  }

 private:
  uint32_t source_mip_;
};

}  // namespace

uint32_t irradiance_source_mip(const Image& env, uint32_t source_mip) {
  uint32_t mip = std::min(source_mip, env.desc().mips - 1);
  while ((env.desc().width >> mip) > kIrradianceMaxSourceFace && mip + 1 < env.desc().mips) ++mip;
  return mip;
}

void record_irradiance(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                       uint32_t source_mip, Image& env, VkSampler sampler, Image& irradiance) {
  const Pipeline& pipeline =
      pipelines.compute({name,
                         node_shader("nodes/env/irradiance/shaders/irradiance.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}});
  const uint32_t mip = irradiance_source_mip(env, source_mip);
  const DescriptorWrite writes[] = {
      sampled_image(0, env.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1}), sampler),
      storage_image(1, irradiance.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = 0, .mip_count = 1}))};
  bind_pipeline(gpu, cmd, pipeline, writes);
  const uint32_t size = irradiance.desc().width;
  vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
}

std::unique_ptr<NodeKernel> make_irradiance_kernel(const PlanNode& node) {
  return std::make_unique<IrradianceKernel>(node);
}

}  // namespace lg
