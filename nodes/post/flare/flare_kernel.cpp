#include "nodes/post/flare/flare_kernel.h"

#include <stdexcept>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/image.h"

namespace lg {
namespace {

struct BrightPush {  // shaders/flare_bright.comp
  float threshold;
  int32_t divisor;
};

struct FeaturesPush {  // shaders/flare_features.comp
  std::array<float, kFlareMaxGhosts> ghost_scales;
  int32_t ghosts;
  float chromatic, halo_radius;
  int32_t streaks, streak_taps;
  float streak_step;
  float ghost_weight, halo_weight, streak_weight;
};

struct CompositePush {  // shaders/flare_composite.comp
  float intensity;
  int32_t divisor;
};

class FlareKernel final : public NodeKernel {
 public:
  explicit FlareKernel(const PlanNode& node) : s_(flare_settings(node)) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "bright")
      bright(ctx);
    else if (pass == "features")
      features(ctx);
    else if (pass == "normalise")
      normalise(ctx);
    else if (pass == "composite")
      composite(ctx);
    else
      throw std::logic_error("post.flare has no pass '" + pass + "'");
  }

 private:
  void bright(PassContext& ctx) {
    Image& grid = ctx.image("tmp.bright");
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler()),
                                      storage_image(1, grid.view())};
    const BrightPush push{float(s_.threshold), s_.divisor};
    dispatch_compute(ctx, "nodes/post/flare/shaders/flare_bright.comp", writes, grid.desc().width, grid.desc().height,
                     std::as_bytes(std::span(&push, 1)));
  }

  void features(PassContext& ctx) {
    Image& flare = ctx.image("tmp.flare");
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("tmp.bright").view(), ctx.linear_sampler()),
                                      storage_image(1, flare.view())};
    const std::array<double, 3> weights = flare_feature_weights(s_);
    const double streak_texels = s_.streak_length * flare.desc().width;
    const int taps = flare_streak_taps(streak_texels);
    const FeaturesPush push{
        kFlareGhostScales,           s_.ghosts,         float(s_.chromatic), float(s_.halo_radius), s_.streaks, taps,
        float(streak_texels / taps), float(weights[0]), float(weights[1]),   float(weights[2])};
    dispatch_compute(ctx, "nodes/post/flare/shaders/flare_features.comp", writes, flare.desc().width,
                     flare.desc().height, std::as_bytes(std::span(&push, 1)));
  }

  void normalise(PassContext& ctx) {
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("tmp.bright").view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("tmp.flare").view(), ctx.nearest_sampler()),
                                      storage_image(2, ctx.image("tmp.guard").view())};
    dispatch_compute(ctx, "nodes/post/flare/shaders/flare_normalise.comp", writes, 1, 1, {}, 1);
  }

  void composite(PassContext& ctx) {
    Image& result = ctx.image("out.color");
    const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("tmp.flare").view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("tmp.guard").view(), ctx.nearest_sampler()),
                                      storage_image(3, result.view())};
    const CompositePush push{float(s_.intensity), s_.divisor};
    dispatch_compute(ctx, "nodes/post/flare/shaders/flare_composite.comp", writes, result.desc().width,
                     result.desc().height, std::as_bytes(std::span(&push, 1)));
  }

  FlareSettings s_;
};

}  // namespace

FlareSettings flare_settings(const PlanNode& node) {
  FlareSettings s;
  s.intensity = param_number(node, "intensity");
  s.threshold = param_number(node, "threshold");
  s.divisor = resolution_divisor(node);
  s.ghosts = int(param_number(node, "ghosts"));
  s.ghost_weight = param_number(node, "ghost_weight");
  s.chromatic = param_number(node, "chromatic");
  s.halo_weight = param_number(node, "halo_weight");
  s.halo_radius = param_number(node, "halo_radius");
  s.streak_weight = param_number(node, "streak_weight");
  s.streaks = int(param_number(node, "streaks"));
  s.streak_length = param_number(node, "streak_length");
  return s;
}

std::unique_ptr<NodeKernel> make_flare_kernel(const PlanNode& node) {
  return std::make_unique<FlareKernel>(node);
}

}  // namespace lg
