#include "nodes/post/bilateral/bilateral_kernel.h"

#include <array>
#include <span>
#include <stdexcept>
#include <string>

#include "nodes/common/compute.h"
#include "nodes/common/guide_extent.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

struct Push {  // shaders/bilateral_common.glsl
  int32_t radius;
  float spatial_falloff, depth_falloff, normal_falloff;
  int32_t direction[2];
  int32_t coverage_in_alpha;
};

float falloff(double sigma) {
  return float(1.0 / (2.0 * sigma * sigma));
}

class BilateralKernel final : public NodeKernel {
 public:
  explicit BilateralKernel(const PlanNode& node)
      : separable_(param_string(node, "kernel") == "separable"),
        push_{int32_t(param_number(node, "radius")),
              falloff(param_number(node, "sigma_spatial")),
              falloff(param_number(node, "sigma_depth")),
              falloff(param_number(node, "sigma_normal")),
              {0, 0},
              0} {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    Image& color = ctx.image("in.color");
    require_guide_size(ctx.node(), "color", color.desc(), ctx.image("in.gbuffer", 0).desc());
    if (pass == "rows") {
      if (separable_) filter(ctx, color, ctx.image("tmp.rows"), {1, 0}, false);
    } else if (pass == "filter") {
      if (separable_)
        filter(ctx, ctx.image("tmp.rows"), ctx.image("out.color"), {0, 1}, true);
      else
        filter(ctx, color, ctx.image("out.color"), {0, 0}, false);
    } else {
      throw std::logic_error("post.bilateral has no pass '" + pass + "'");
    }
  }

 private:
  // One dispatch from `source` into `target`: along `direction`, or the full square at (0, 0).
  void filter(PassContext& ctx, Image& source, Image& target, std::array<int32_t, 2> direction, bool coverage) {
    Push push = push_;
    push.direction[0] = direction[0], push.direction[1] = direction[1];
    push.coverage_in_alpha = coverage ? 1 : 0;
    const DescriptorWrite writes[] = {sampled_image(0, source.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.color").view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(3, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(4, target.view())};
    const bool full = direction[0] == 0 && direction[1] == 0;
    dispatch_compute(
        ctx,
        full ? "nodes/post/bilateral/shaders/bilateral_full.comp" : "nodes/post/bilateral/shaders/bilateral_line.comp",
        writes, target.desc().width, target.desc().height, std::as_bytes(std::span(&push, 1)));
  }

  bool separable_;
  Push push_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_bilateral_kernel(const PlanNode& node) {
  return std::make_unique<BilateralKernel>(node);
}

}  // namespace lg
