#include "nodes/occlusion/ssao/ssao_kernel.h"

#include <optional>
#include <stdexcept>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct Constants {  // nodes/occlusion/ssao/shaders/ssao_constants.glsl
  CameraConstants camera;
  glm::vec4 settings;
  uint32_t counts[4];
};

class SsaoKernel final : public NodeKernel {
 public:
  explicit SsaoKernel(const PlanNode& node)
      : samples_(uint32_t(param_number(node, "samples"))),
        radius_(float(param_number(node, "radius"))),
        bias_(float(param_number(node, "bias"))) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    Image& depth = ctx.image("in.gbuffer", 0);
    if (pass == "sample") {
      Image& noisy = ctx.image("tmp.noisy");
      write_constants(ctx, noisy);
      const DescriptorWrite writes[] = {
          uniform_buffer(0, constants_->handle()), sampled_image(1, depth.view(), ctx.nearest_sampler()),
          sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()), storage_image(3, noisy.view())};
      dispatch_compute(ctx, "nodes/occlusion/ssao/shaders/sample.comp", writes, noisy.desc().width,
                       noisy.desc().height);
    } else if (pass == "blur") {
      Image& ao = ctx.image("out.ao");
      const DescriptorWrite writes[] = {
          uniform_buffer(0, constants_->handle()), sampled_image(1, depth.view(), ctx.nearest_sampler()),
          sampled_image(2, ctx.image("tmp.noisy").view(), ctx.nearest_sampler()), storage_image(3, ao.view())};
      dispatch_compute(ctx, "nodes/occlusion/ssao/shaders/blur.comp", writes, ao.desc().width, ao.desc().height);
    } else {
      throw std::logic_error("occlusion.ssao has no pass '" + pass + "'");
    }
  }

 private:
  void write_constants(PassContext& ctx, const Image& target) {
    if (!constants_) constants_.emplace(ctx.gpu(), ctx.node().id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    const CameraView& camera = ctx.scene().camera;
    Constants c{};
    c.camera = camera_constants(camera, target.desc().width, target.desc().height);
    c.settings = glm::vec4(radius_, bias_, camera.near_plane, 0.0f);
    c.counts[0] = samples_;
    c.counts[1] = uint32_t(ctx.frame_index());
    constants_->write_value(c);
  }

  uint32_t samples_;
  float radius_, bias_;
  std::optional<HostBuffer> constants_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_ssao_kernel(const PlanNode& node) {
  return std::make_unique<SsaoKernel>(node);
}

}  // namespace lg
