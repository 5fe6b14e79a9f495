#include "nodes/post/tonemap/tonemap_kernel.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

struct Push {  // nodes/post/tonemap/shaders/tonemap.comp
  float exposure_scale;
};

uint32_t curve_index(const PlanNode& node) {
  const std::string& curve = param_string(node, "curve");
  if (curve == "aces_fitted") return 0;
  if (curve == "neutral") return 1;
  if (curve == "clamp") return 2;
  throw std::logic_error("post.tonemap has no curve '" + curve + "'");
}

class TonemapKernel final : public NodeKernel {
 public:
  explicit TonemapKernel(const PlanNode& node)
      : push_{float(std::exp2(param_number(node, "exposure")))}, curve_(curve_index(node)) {}

  void record(PassContext& ctx) override {
    Image& display = ctx.image("out.color");
    const uint32_t auto_exposure = ctx.has("in.auto_exposure") ? 1u : 0u;
    // Unlinked, the colour stands in at the exposure's binding, and the shader does not read it.
    const VkImageView exposure = ctx.image(auto_exposure ? "in.auto_exposure" : "in.color").view();
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler()),
                                      storage_image(1, display.view()),
                                      sampled_image(2, exposure, ctx.nearest_sampler())};
    dispatch_compute(ctx, "nodes/post/tonemap/shaders/tonemap.comp", writes, display.desc().width,
                     display.desc().height, std::as_bytes(std::span(&push_, 1)), kTileSize,
                     std::array{curve_, auto_exposure});  // tonemap.comp's specialization constants
  }

 private:
  Push push_;
  uint32_t curve_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_tonemap_kernel(const PlanNode& node) {
  return std::make_unique<TonemapKernel>(node);
}

}  // namespace lg
