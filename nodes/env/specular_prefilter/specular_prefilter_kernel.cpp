#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/env/specular_prefilter/exact_prefilter.h"
#include "runtime/gpu/buffer.h"
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

struct ChainPush {  // nodes/env/specular_prefilter/shaders/prefilter_chain.comp
  uint32_t first;
};

class SpecularPrefilterKernel final : public NodeKernel {
 public:
  explicit SpecularPrefilterKernel(const PlanNode& node)
      : exact_(param_string(node, "method") == "exact"), samples_(uint32_t(param_number(node, "samples"))) {}

  void record(PassContext& ctx) override {
    // The exact sums read a power-of-two chain (16^2 a face and finer levels from it); other
    // face sizes are prefiltered by sampling.
    if (!exact_ || !std::has_single_bit(ctx.image("in.env").desc().width)) {
      record_specular_prefilter(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, samples_, ctx.image("in.env"),
                                &ctx.image("tmp.chain"), ctx.linear_sampler(), ctx.image("out.specular"),
                                PrefilterSampling::filtered);
      return;
    }
    if (peaks_.size() < prefilter_peaks_bytes())
      peaks_ =
          Buffer::dedicated(ctx.gpu(), {.name = ctx.node().id + " prefilter peaks", .size = prefilter_peaks_bytes()});
    record_specular_prefilter_exact(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, ctx.image("in.env"),
                                    ctx.image("tmp.chain"), ctx.nearest_sampler(), peaks_, ctx.image("out.specular"));
  }

 private:
  bool exact_;
  uint32_t samples_;
  Buffer peaks_;  // the exact method's peak list, the node's own (as env.sh_project's partial sums)
};

// Level 0: the input's mip 0; each further level from the one above, read in GENERAL, where the
// chain stays during the pass.
void record_prefilter_chain(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                            Image& env, VkSampler trilinear, Image& chain) {
  if (chain.desc().width != env.desc().width)
    throw std::invalid_argument("env.specular_prefilter: the chain's faces (" + std::to_string(chain.desc().width) +
                                ") differ from the environment's (" + std::to_string(env.desc().width) + ")");
  const Pipeline& pipeline =
      pipelines.compute({name,
                         node_shader("nodes/env/specular_prefilter/shaders/prefilter_chain.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                          {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                          {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}},
                         sizeof(ChainPush)});
  for (uint32_t mip = 0; mip < chain.desc().mips; ++mip) {
    if (mip > 0) compute_to_compute_barrier(cmd);
    const uint32_t size = std::max(1u, chain.desc().width >> mip);
    // Level 0 fetches binding 2; the others read binding 0, which level 0 fills with the input.
    const DescriptorWrite writes[] = {
        mip == 0
            ? sampled_image(0, env.view(), trilinear)
            : sampled_image(0, chain.view({.base_mip = mip - 1, .mip_count = 1}), trilinear, VK_IMAGE_LAYOUT_GENERAL),
        storage_image(1, chain.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1})),
        sampled_image(2, env.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = 0, .mip_count = 1}), trilinear)};
    bind_pipeline(gpu, cmd, pipeline, writes);
    push_constants(cmd, pipeline, ChainPush{mip == 0 ? 1u : 0u});
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
  compute_to_compute_barrier(cmd);
}

}  // namespace

void record_specular_prefilter(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                               uint32_t samples, Image& env, Image* chain, VkSampler trilinear, Image& prefiltered,
                               PrefilterSampling sampling) {
  const bool filtered = sampling == PrefilterSampling::filtered;
  if (filtered) {
    if (!chain) throw std::invalid_argument("env.specular_prefilter: filtered sampling needs a chain");
    record_prefilter_chain(gpu, pipelines, cmd, name, env, trilinear, *chain);
  }
  const Pipeline& pipeline = pipelines.compute({name,
                                                node_shader("nodes/env/specular_prefilter/shaders/prefilter.comp"),
                                                {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                                 {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                                 {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}},
                                                sizeof(Push)});
  const uint32_t mips = prefiltered.desc().mips;
  for (uint32_t mip = 0; mip < mips; ++mip) {
    const uint32_t size = std::max(1u, prefiltered.desc().width >> mip);
    const DescriptorWrite writes[] = {
        sampled_image(0, env.view(), trilinear),
        storage_image(1, prefiltered.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1})),
        // What the samples read: the chain (filtered), the input's mip 0 (plain).
        filtered ? sampled_image(2, chain->view(), trilinear, VK_IMAGE_LAYOUT_GENERAL)
                 : sampled_image(2, env.view(), trilinear)};
    bind_pipeline(gpu, cmd, pipeline, writes);
    push_constants(
        cmd, pipeline,
        Push{float(prefilter_roughness(mip, mips)), std::clamp(samples, 1u, kMaxPrefilterSamples), filtered ? 1u : 0u});
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
}

std::unique_ptr<NodeKernel> make_specular_prefilter_kernel(const PlanNode& node) {
  return std::make_unique<SpecularPrefilterKernel>(node);
}

}  // namespace lg
