#include "nodes/occlusion/gtao/gtao_kernel.h"

#include <algorithm>
#include <cmath>
#include <glm/matrix.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "nodes/common/compute.h"
#include "nodes/common/history.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/camera_jitter.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

struct Constants {  // nodes/occlusion/gtao/shaders/gtao_constants.glsl
  glm::mat4 view_from_world, world_from_view;
  glm::vec4 unproject, viewport, search;
  uint32_t counts[4];
  glm::vec4 blend;
};

struct Quality {
  uint32_t slices, steps;  // steps per side of each slice
};

// On the measured error-against-time envelope (docs/bench/ao): on lavapipe a slice costs far
// more than a step, and the error falls mostly with steps, so the presets add steps first.
Quality quality_preset(const std::string& name) {
  if (name == "low") return {1, 4};
  if (name == "medium") return {1, 8};
  if (name == "high") return {2, 6};
  if (name == "ultra") return {4, 8};
  throw std::logic_error("occlusion.gtao has no quality '" + name + "'");
}

// The preset, with the `slices` and `steps` params in its place where they are not 0.
Quality quality_of(const PlanNode& node) {
  Quality q = quality_preset(param_string(node, "quality"));
  if (const auto slices = uint32_t(param_number(node, "slices"))) q.slices = slices;
  if (const auto steps = uint32_t(param_number(node, "steps"))) q.steps = steps;
  return q;
}

class GtaoKernel final : public NodeKernel {
 public:
  explicit GtaoKernel(const PlanNode& node)
      : quality_(quality_of(node)),
        radius_(float(param_number(node, "radius"))),
        thickness_(float(param_number(node, "thickness"))),
        temporal_blend_(float(param_number(node, "temporal_blend"))),
        k_(resolution_divisor(node)) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "prefilter")
      prefilter(ctx);
    else if (pass == "horizons")
      horizons(ctx);
    else if (pass == "denoise")
      denoise(ctx);
    else if (pass == "upsample")
      upsample(ctx);
    else
      throw std::logic_error("occlusion.gtao has no pass '" + pass + "'");
  }

 private:
  bool full_resolution() const { return k_ == 1; }

  // Once a frame, by its first pass; `target` has the G-buffer's extent.
  void write_constants(PassContext& ctx, const Image& target) {
    if (written_frame_ == ctx.frame_index() && constants_) return;
    written_frame_ = ctx.frame_index();
    if (!constants_) constants_.emplace(ctx.gpu(), ctx.node().id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    const CameraView& camera = ctx.scene().camera;
    const float w = float(target.desc().width), h = float(target.desc().height);
    const glm::mat4 p = jittered_projection(camera);  // as the G-buffer's depth was rasterized
    Constants c{};
    c.view_from_world = camera.view;
    c.world_from_view = glm::inverse(camera.view);
    c.unproject = glm::vec4(1.0f / p[0][0], 1.0f / p[1][1], p[2][0], p[2][1]);
    c.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    // Thin surfaces seen edge-on occlude less: depth differences count up to 1.5 times in the
    // falloff, the more so the thinner surfaces are assumed against the radius.
    const float stretch = 1.0f + 0.5f * std::min(1.0f, radius_ / (4.0f * std::max(thickness_, 1e-4f)));
    c.search = glm::vec4(radius_, 0.5f * h * std::abs(p[1][1]), stretch, 0.25f * std::max(w, h));
    c.counts[2] = uint32_t(ctx.frame_index());
    c.counts[3] = 0;  // the denoiser's pass says whether the history is usable (use_history)
    c.blend = glm::vec4(temporal_blend_, camera.near_plane, float(k_), 0.0f);
    constants_->write_value(c);
    written_ = c;
  }

  // Not the cleared history of the first frame (it would read as full occlusion), nor after a cut.
  // Only a pass that uses in.history sees it (PassContext::has is per pass): when the first pass
  // wrote the constants, the history was never blended (found by gtao_history_test.cpp). The
  // constants are read when the frame runs, after every pass is recorded.
  void use_history(PassContext& ctx) {
    written_.counts[3] = history_usable(ctx, "in.history") ? 1u : 0u;
    constants_->write_value(written_);
  }

  void prefilter(PassContext& ctx) {
    Image& mips = ctx.image("tmp.depth_mips");
    write_constants(ctx, ctx.image("in.gbuffer", 0));
    std::vector<DescriptorWrite> writes = {uniform_buffer(0, constants_->handle()),
                                           sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler())};
    // A small image has fewer mips than the shader writes: the extra levels go to the last one.
    for (uint32_t level = 0; level < 5; ++level) {
      const uint32_t mip = std::min(level, mips.desc().mips - 1);
      writes.push_back(storage_image(2 + level, mips.view({.base_mip = mip, .mip_count = 1})));
    }
    // One invocation a 2x2 quad of grid texels, 8x8 invocations a 16x16 tile.
    dispatch_compute(ctx, "nodes/occlusion/gtao/shaders/prefilter.comp", writes, (mips.desc().width + 1) / 2,
                     (mips.desc().height + 1) / 2, {}, 8);
  }

  // On the grid of resolution_scale (noisy's extent, as the depth mips' first level), reading
  // the normal at each texel's G-buffer pixel.
  void horizons(PassContext& ctx) {
    Image& noisy = ctx.image("tmp.noisy");
    Image& depth_mips = ctx.image("tmp.depth_mips");
    write_constants(ctx, ctx.image("in.gbuffer", 1));
    Image& bent = ctx.image(full_resolution() ? "out.bent_normals" : "tmp.bent_low");
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()),
                                      sampled_image(1, depth_mips.view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(3, noisy.view()),
                                      storage_image(4, ctx.image("tmp.edges").view()),
                                      storage_image(5, bent.view()),
                                      storage_image(6, ctx.image("tmp.surface").view())};
    const uint32_t specialization[] = {quality_.slices, quality_.steps, uint32_t(k_)};  // horizons.comp's
    dispatch_compute(ctx, "nodes/occlusion/gtao/shaders/horizons.comp", writes, noisy.desc().width, noisy.desc().height,
                     {}, kTileSize, specialization);
  }

  // On the same grid; the history it blends is the full-resolution output of the last frame.
  // From noisy into out.ao at resolution_scale 1, else from surface into ao_guide.
  void denoise(PassContext& ctx) {
    write_constants(ctx, ctx.image("in.gbuffer", 4));
    use_history(ctx);
    Image& noisy = ctx.image(full_resolution() ? "tmp.noisy" : "tmp.surface");
    Image& history = ctx.has("in.history") ? ctx.image("in.history") : noisy;
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()),
                                      sampled_image(1, noisy.view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("tmp.edges").view(), ctx.nearest_sampler()),
                                      sampled_image(3, ctx.image("in.gbuffer", 4).view(), ctx.nearest_sampler()),
                                      sampled_image(4, history.view(), ctx.linear_sampler()),
                                      storage_image(5, ctx.image("out.ao").view()),
                                      storage_image(6, ctx.image("tmp.ao_guide").view())};
    const uint32_t divisor[] = {uint32_t(k_)};  // denoise.comp's specialization
    dispatch_compute(ctx, "nodes/occlusion/gtao/shaders/denoise.comp", writes, (noisy.desc().width + 1) / 2,
                     (noisy.desc().height + 1) / 2, {}, 8, divisor);  // 2x2 texels an invocation
  }

  // One invocation per grid texel, each writing its block of k x k pixels. At full resolution
  // the horizons and the denoiser wrote the outputs themselves, and there is nothing to do.
  void upsample(PassContext& ctx) {
    if (full_resolution()) return;
    Image& low = ctx.image("tmp.ao_guide");
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("tmp.bent_low").view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      storage_image(4, ctx.image("out.ao").view()),
                                      storage_image(5, ctx.image("out.bent_normals").view())};
    dispatch_compute(ctx, "nodes/occlusion/gtao/shaders/upsample.comp", writes, low.desc().width, low.desc().height,
                     std::as_bytes(std::span(&k_, 1)));
  }

  Quality quality_;
  float radius_, thickness_, temporal_blend_;
  int32_t k_;  // 1 / resolution_scale: the G-buffer's resolution over the horizon grid's
  std::optional<HostBuffer> constants_;
  Constants written_{};
  uint64_t written_frame_ = ~uint64_t{0};
};

}  // namespace

std::unique_ptr<NodeKernel> make_gtao_kernel(const PlanNode& node) {
  return std::make_unique<GtaoKernel>(node);
}

}  // namespace lg
