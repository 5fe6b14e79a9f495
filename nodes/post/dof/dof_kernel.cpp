#include "nodes/post/dof/dof_kernel.h"

#include <cmath>
#include <stdexcept>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct Push {  // shaders/dof_constants.glsl
  float coc_scale, focus, near_plane, max_blur;
  uint32_t samples;
};

// A thin lens of aperture diameter A focused at F, its sensor at the focus plane's image
// distance v (what the field of view fixes: tan(fov / 2) = (S / 2) / v for a sensor S tall; the
// focal length is then 1 / (1 / v + 1 / F)). A point at depth z blurs into a circle of diameter
// A v |1 / F - 1 / z| on the sensor, h / S pixels a metre: A (h / 2) / tan(fov / 2) |1 / F - 1 / z|
// pixels, whatever the sensor's size. It is exactly the spread of pinhole views taken over the
// aperture disc and re-aimed at the focus plane (tests/post/thin_lens_reference.h).
Push lens(const CameraView& camera, float max_blur, uint32_t samples, uint32_t height) {
  const float image_distance_pixels = 0.5f * float(height) / std::tan(0.5f * camera.vertical_fov);
  const float coc_scale = 0.5f * camera.aperture * image_distance_pixels;  // a radius
  return {coc_scale, camera.focus_distance, camera.near_plane, max_blur, samples};
}

class DofKernel final : public NodeKernel {
 public:
  explicit DofKernel(const PlanNode& node)
      : max_blur_(float(param_number(node, "max_blur"))), samples_(uint32_t(param_number(node, "samples"))) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    Image& coc = ctx.image("tmp.coc");
    const Push push = lens(ctx.scene().camera, max_blur_, samples_, coc.desc().height);
    const auto bytes = std::as_bytes(std::span(&push, 1));
    if (pass == "coc") {
      const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                        storage_image(1, coc.view())};
      dispatch_compute(ctx, "nodes/post/dof/shaders/dof_coc.comp", writes, coc.desc().width, coc.desc().height, bytes);
    } else if (pass == "gather") {
      Image& blurred = ctx.image("tmp.blurred");
      const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.linear_sampler()),
                                        sampled_image(1, coc.view(), ctx.nearest_sampler()),
                                        storage_image(2, blurred.view())};
      dispatch_compute(ctx, "nodes/post/dof/shaders/dof_gather.comp", writes, blurred.desc().width,
                       blurred.desc().height, bytes);
    } else if (pass == "composite") {
      Image& result = ctx.image("out.color");
      const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler()),
                                        sampled_image(1, coc.view(), ctx.nearest_sampler()),
                                        sampled_image(2, ctx.image("tmp.blurred").view(), ctx.linear_sampler()),
                                        storage_image(3, result.view())};
      dispatch_compute(ctx, "nodes/post/dof/shaders/dof_composite.comp", writes, result.desc().width,
                       result.desc().height, bytes);
    } else {
      throw std::logic_error("post.dof has no pass '" + pass + "'");
    }
  }

 private:
  float max_blur_;
  uint32_t samples_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_dof_kernel(const PlanNode& node) {
  return std::make_unique<DofKernel>(node);
}

}  // namespace lg
