#include "nodes/post/taa/taa_kernel.h"

#include <optional>
#include <span>
#include <stdexcept>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/history.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct ResolvePush {  // shaders/resolve.comp
  float feedback;
  float clip_sigma;
  float depth_tolerance;
  uint32_t use_history;
};

class TaaKernel final : public NodeKernel {
 public:
  explicit TaaKernel(const PlanNode& node)
      : resolve_{float(param_number(node, "feedback")), float(param_number(node, "clip_sigma")),
                 float(param_number(node, "depth_tolerance")), 0u},
        sharpen_(float(param_number(node, "sharpen"))) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "resolve")
      resolve(ctx);
    else if (pass == "sharpen")
      sharpen(ctx);
    else
      throw std::logic_error("post.taa has no pass '" + pass + "'");
  }

 private:
  void resolve(PassContext& ctx) {
    Image& target = ctx.image("out.accumulated");
    const uint32_t w = target.desc().width, h = target.desc().height;
    if (!camera_) camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    camera_->write_value(camera_constants(ctx.scene().camera, w, h));
    const bool history = ctx.has("in.history");
    ResolvePush push = resolve_;
    push.use_history = history_usable(ctx, "in.history") ? 1u : 0u;
    Image& color = ctx.image("in.color");
    // Unlinked history: the colour stands in at its binding, and the shader does not read it.
    Image& past = history ? ctx.image("in.history") : color;
    const DescriptorWrite writes[] = {uniform_buffer(0, camera_->handle()),
                                      sampled_image(1, color.view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(3, ctx.image("in.gbuffer", 4).view(), ctx.nearest_sampler()),
                                      sampled_image(4, past.view(), ctx.linear_sampler()),
                                      storage_image(5, target.view())};
    dispatch_compute(ctx, "nodes/post/taa/shaders/resolve.comp", writes, w, h, std::as_bytes(std::span(&push, 1)));
  }

  void sharpen(PassContext& ctx) {
    Image& result = ctx.image("out.color");
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("out.accumulated").view(), ctx.nearest_sampler()),
                                      storage_image(1, result.view())};
    dispatch_compute(ctx, "nodes/post/taa/shaders/sharpen.comp", writes, result.desc().width, result.desc().height,
                     std::as_bytes(std::span(&sharpen_, 1)));
  }

  ResolvePush resolve_;
  float sharpen_;
  std::optional<HostBuffer> camera_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_taa_kernel(const PlanNode& node) {
  return std::make_unique<TaaKernel>(node);
}

}  // namespace lg
