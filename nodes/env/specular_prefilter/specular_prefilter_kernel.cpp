#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"

#include <algorithm>

#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"

namespace lg {
namespace {

constexpr uint32_t kGroup = 8;

struct Push {  // nodes/env/specular_prefilter/shaders/prefilter.comp
  float roughness;
  uint32_t samples;
  uint32_t filtered;
};

class SpecularPrefilterKernel final : public NodeKernel {
 public:
  explicit SpecularPrefilterKernel(const PlanNode& node) : samples_(uint32_t(param_number(node, "samples"))) {}

  void record(PassContext& ctx) override {
    record_specular_prefilter(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, samples_, ctx.image("in.env"),
                              ctx.linear_sampler(), ctx.image("out.specular"), PrefilterSampling::filtered);
  }

 private:
  uint32_t samples_;
};

}  // namespace

void record_specular_prefilter(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                               uint32_t samples, Image& env, VkSampler trilinear, Image& prefiltered,
                               PrefilterSampling sampling) {
  const Pipeline& pipeline =
      pipelines.compute({name,
                         node_shader("nodes/env/specular_prefilter/shaders/prefilter.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                         sizeof(Push)});
  const uint32_t mips = prefiltered.desc().mips;
  for (uint32_t mip = 0; mip < mips; ++mip) {
    const uint32_t size = std::max(1u, prefiltered.desc().width >> mip);
    const DescriptorWrite writes[] = {
        sampled_image(0, env.view(), trilinear),
        storage_image(1, prefiltered.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1}))};
    bind_pipeline(gpu, cmd, pipeline, writes);
    push_constants(cmd, pipeline,
                   Push{float(prefilter_roughness(mip, mips)), std::clamp(samples, 1u, kMaxPrefilterSamples),
                        sampling == PrefilterSampling::filtered ? 1u : 0u});
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
}

std::unique_ptr<NodeKernel> make_specular_prefilter_kernel(const PlanNode& node) {
  return std::make_unique<SpecularPrefilterKernel>(node);
}

}  // namespace lg
