#include "nodes/lighting/ssr/ssr_kernel.h"

#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/history.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct TracePush {  // nodes/lighting/ssr/shaders/trace.comp
  uint32_t max_steps, flags, frame;
  float max_roughness, thickness, max_distance, edge_fade, near_plane;
  int32_t k;
};

struct ResolvePush {  // nodes/lighting/ssr/shaders/resolve.comp
  uint32_t flags;
  float temporal_blend, max_roughness;
  int32_t k;
};

struct UpsamplePush {  // nodes/lighting/ssr/shaders/upsample.comp
  int32_t k;
  float max_roughness;
};

class SsrKernel final : public NodeKernel {
 public:
  explicit SsrKernel(const PlanNode& node)
      : max_steps_(uint32_t(param_number(node, "max_steps"))),
        max_roughness_(float(param_number(node, "max_roughness"))),
        thickness_(float(param_number(node, "thickness"))),
        max_distance_(float(param_number(node, "max_distance"))),
        edge_fade_(float(param_number(node, "edge_fade"))),
        spatial_reuse_(param_bool(node, "spatial_reuse")),
        temporal_blend_(float(param_number(node, "temporal_blend"))),
        k_(resolution_divisor(node)) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "hiz")
      build_pyramid(ctx);
    else if (pass == "trace")
      trace(ctx);
    else if (pass == "resolve")
      resolve(ctx);
    else if (pass == "upsample")
      upsample(ctx);
    else
      throw std::logic_error("lighting.ssr has no pass '" + pass + "'");
  }

 private:
  // One dispatch a level, each reading the one before it.
  void build_pyramid(PassContext& ctx) {
    Image& hiz = ctx.image("tmp.pyramid");
    for (uint32_t level = 0; level < hiz.desc().mips; ++level) {
      // Also before level 0: its shader declares a read of `below`, which must follow the
      // plan's layout transition (made visible to writes only).
      compute_to_compute_barrier(ctx.cmd());
      const uint32_t below = level > 0 ? level - 1 : 0;
      const DescriptorWrite writes[] = {sampled_image(0, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                        storage_image(1, hiz.view({.base_mip = below, .mip_count = 1})),
                                        storage_image(2, hiz.view({.base_mip = level, .mip_count = 1}))};
      dispatch_compute(ctx, "nodes/lighting/ssr/shaders/hiz.comp", writes, std::max(1u, hiz.desc().width >> level),
                       std::max(1u, hiz.desc().height >> level), std::as_bytes(std::span(&level, 1)));
    }
  }

  bool full_resolution() const { return k_ == 1; }

  // On the grid of resolution_scale (raw's extent), each texel the ray of its G-buffer pixel.
  void trace(PassContext& ctx) {
    Image& out = ctx.image("tmp.raw");
    if (!camera_) camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    const CameraView& camera = ctx.scene().camera;
    const ImageDesc& full = ctx.image("tmp.pyramid").desc();
    camera_->write_value(camera_constants(camera, full.width, full.height));
    // Not the cleared history of the first frame (black, not last frame's light), nor after a cut.
    const bool history = history_usable(ctx, "in.history");
    last_frame_lit_ = this_frame_lit_;
    this_frame_lit_ = history || !ctx.has("in.history");  // unlinked: `color` is all there is
    Image& color = ctx.image("in.color");
    const DescriptorWrite writes[] = {
        uniform_buffer(0, camera_->handle()),
        sampled_image(1, ctx.image("tmp.pyramid").view(), ctx.nearest_sampler()),
        sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        sampled_image(4, ctx.image("in.gbuffer", 4).view(), ctx.nearest_sampler()),
        sampled_image(5, color.view(), ctx.nearest_sampler()),
        sampled_image(6, (ctx.has("in.history") ? ctx.image("in.history") : color).view(), ctx.linear_sampler()),
        storage_image(7, out.view())};
    const TracePush push{max_steps_,     history ? 1u : 0u, uint32_t(ctx.frame_index()),
                         max_roughness_, thickness_,        max_distance_,
                         edge_fade_,     camera.near_plane, k_};
    dispatch_compute(ctx, "nodes/lighting/ssr/shaders/trace.comp", writes, out.desc().width, out.desc().height,
                     std::as_bytes(std::span(&push, 1)));
  }

  // On the same grid: straight into the output at full resolution, else for the upsample.
  void resolve(PassContext& ctx) {
    Image& out = ctx.image(full_resolution() ? "out.reflections" : "tmp.resolved");
    Image& raw = ctx.image("tmp.raw");
    // Last frame's result, unless it is the cleared history of the first frame, a cut, or its hits
    // reflected an incomplete image: `color` alone (the direct light) while a lit history was
    // linked but not yet drawn. Carried at temporal_blend, that first frame would darken the
    // reflections for tens of frames (0.9^7 = 48% of them after 8 frames at the default).
    const bool history = history_usable(ctx, "in.reflection_history") && last_frame_lit_;
    const DescriptorWrite writes[] = {
        sampled_image(0, raw.view(), ctx.nearest_sampler()),
        sampled_image(1, ctx.image("tmp.pyramid").view({.base_mip = 0, .mip_count = 1}), ctx.nearest_sampler()),
        sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        sampled_image(4, ctx.image("in.gbuffer", 4).view(), ctx.nearest_sampler()),
        sampled_image(5, (ctx.has("in.reflection_history") ? ctx.image("in.reflection_history") : raw).view(),
                      ctx.linear_sampler()),
        storage_image(6, out.view())};
    const ResolvePush push{(history ? 1u : 0u) | (spatial_reuse_ ? 2u : 0u), temporal_blend_, max_roughness_, k_};
    dispatch_compute(ctx, "nodes/lighting/ssr/shaders/resolve.comp", writes, out.desc().width, out.desc().height,
                     std::as_bytes(std::span(&push, 1)));
  }

  // One invocation per grid texel, each writing its block of k x k pixels; nothing at full
  // resolution, where the resolve wrote the output itself.
  void upsample(PassContext& ctx) {
    if (full_resolution()) return;
    Image& low = ctx.image("tmp.resolved");
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      sampled_image(3, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
                                      storage_image(4, ctx.image("out.reflections").view())};
    const UpsamplePush push{k_, max_roughness_};
    dispatch_compute(ctx, "nodes/lighting/ssr/shaders/upsample.comp", writes, low.desc().width, low.desc().height,
                     std::as_bytes(std::span(&push, 1)));
  }

  uint32_t max_steps_;
  float max_roughness_, thickness_, max_distance_, edge_fade_;
  bool spatial_reuse_;
  float temporal_blend_;
  int32_t k_;  // 1 / resolution_scale: the G-buffer's resolution over the trace's grid
  // Whether this frame's and the last frame's hits read the complete lit image (set by the trace,
  // read by the resolve).
  bool this_frame_lit_ = false, last_frame_lit_ = false;
  std::optional<HostBuffer> camera_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_ssr_kernel(const PlanNode& node) {
  return std::make_unique<SsrKernel>(node);
}

}  // namespace lg
