#include "nodes/post/upsample/upsample_kernel.h"

#include <span>

#include "nodes/common/compute.h"
#include "nodes/common/guide_extent.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

class UpsampleKernel final : public NodeKernel {
 public:
  void record(PassContext& ctx) override {
    Image& low = ctx.image("in.color");
    Image& depth = ctx.image("in.gbuffer", 0);
    const int32_t k = guide_divisor(ctx.node(), "color", low.desc(), depth.desc());
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, depth.view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(3, ctx.image("out.color").view())};
    dispatch_compute(ctx, "nodes/post/upsample/shaders/upsample.comp", writes, low.desc().width, low.desc().height,
                     std::as_bytes(std::span(&k, 1)));
  }
};

}  // namespace

std::unique_ptr<NodeKernel> make_upsample_kernel(const PlanNode&) {
  return std::make_unique<UpsampleKernel>();
}

}  // namespace lg
