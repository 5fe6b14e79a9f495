#include "nodes/post/bloom/bloom_kernel.h"

#include <algorithm>
#include <stdexcept>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

struct DownsamplePush {  // shaders/bloom_downsample.comp
  float threshold;
  uint32_t first;
};

struct CompositePush {  // shaders/bloom_composite.comp
  float intensity, threshold, levels;
};

uint32_t extent(uint32_t size, uint32_t mip) {
  return std::max(size >> mip, 1u);
}

class BloomKernel final : public NodeKernel {
 public:
  explicit BloomKernel(const PlanNode& node)
      : intensity_(float(param_number(node, "intensity"))), threshold_(float(param_number(node, "threshold"))) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "downsample")
      downsample(ctx);
    else if (pass == "upsample")
      upsample(ctx);
    else if (pass == "composite")
      composite(ctx);
    else
      throw std::logic_error("post.bloom has no pass '" + pass + "'");
  }

 private:
  // Level 0 from the scene, then each level from the one above it (read in GENERAL, where the
  // chain stays during the pass).
  void downsample(PassContext& ctx) {
    Image& chain = ctx.image("tmp.chain");
    for (uint32_t mip = 0; mip < chain.desc().mips; ++mip) {
      if (mip > 0) compute_to_compute_barrier(ctx.cmd());
      VkImageView source = mip == 0 ? ctx.image("in.color").view() : chain.view({.base_mip = mip - 1, .mip_count = 1});
      const DescriptorWrite writes[] = {
          sampled_image(0, source, ctx.linear_sampler(),
                        mip == 0 ? VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL),
          storage_image(1, chain.view({.base_mip = mip, .mip_count = 1}))};
      const DownsamplePush push{threshold_, mip == 0 ? 1u : 0u};
      dispatch_compute(ctx, "nodes/post/bloom/shaders/bloom_downsample.comp", writes, extent(chain.desc().width, mip),
                       extent(chain.desc().height, mip), std::as_bytes(std::span(&push, 1)));
    }
  }

  void upsample(PassContext& ctx) {
    Image& chain = ctx.image("tmp.chain");
    // The plan's barrier before this pass covers storage access; the coarser levels are sampled.
    compute_to_compute_barrier(ctx.cmd());
    for (uint32_t mip = chain.desc().mips - 1; mip-- > 0;) {
      const DescriptorWrite writes[] = {sampled_image(0, chain.view({.base_mip = mip + 1, .mip_count = 1}),
                                                      ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
                                        storage_image(1, chain.view({.base_mip = mip, .mip_count = 1}))};
      dispatch_compute(ctx, "nodes/post/bloom/shaders/bloom_upsample.comp", writes, extent(chain.desc().width, mip),
                       extent(chain.desc().height, mip));
      if (mip > 0) compute_to_compute_barrier(ctx.cmd());
    }
  }

  void composite(PassContext& ctx) {
    Image& result = ctx.image("out.color");
    Image& chain = ctx.image("tmp.chain");
    const DescriptorWrite writes[] = {
        sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler()),
        sampled_image(1, chain.view({.base_mip = 0, .mip_count = 1}), ctx.linear_sampler()),
        storage_image(2, result.view())};
    const CompositePush push{intensity_, threshold_, float(chain.desc().mips)};
    dispatch_compute(ctx, "nodes/post/bloom/shaders/bloom_composite.comp", writes, result.desc().width,
                     result.desc().height, std::as_bytes(std::span(&push, 1)));
  }

  float intensity_, threshold_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_bloom_kernel(const PlanNode& node) {
  return std::make_unique<BloomKernel>(node);
}

}  // namespace lg
