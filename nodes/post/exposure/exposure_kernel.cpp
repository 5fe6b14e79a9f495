#include "nodes/post/exposure/exposure_kernel.h"

#include <cmath>

#include "nodes/common/compute.h"
#include "nodes/common/history.h"
#include "nodes/common/node_params.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

constexpr uint32_t kHistogramTile = 64;  // pixels a workgroup counts: nodes/post/exposure/shaders/histogram.comp

struct Push {  // nodes/post/exposure/shaders/exposure_common.glsl
  float histogram_min, histogram_max;
  float low_fraction, high_fraction;
  float compensation;
  float speed_up, speed_down;
  float seconds;
  uint32_t restart;
};

// A frame time the host got wrong (negative, NaN) adapts nothing rather than spreading.
float usable_seconds(float seconds) {
  return std::isfinite(seconds) && seconds > 0 ? seconds : 0.0f;
}

class ExposureKernel final : public NodeKernel {
 public:
  explicit ExposureKernel(const PlanNode& node) {
    const ExposureSettings s = exposure_settings(node);
    push_ = {float(s.histogram_min),
             float(s.histogram_max),
             float(s.low_percent / 100),
             float(s.high_percent / 100),
             float(s.compensation),
             float(s.speed_up),
             float(s.speed_down),
             0.0f,
             1u};
  }

  void record(PassContext& ctx) override {
    if (ctx.pass().pass == "histogram") return count(ctx);
    meter(ctx);
  }

 private:
  void count(PassContext& ctx) {
    if (!histogram_.handle())
      histogram_ = Buffer::dedicated(
          ctx.gpu(), {.name = ctx.node().id + " exposure histogram", .size = kExposureBins * sizeof(uint32_t)});
    // Last frame's meter read the bins; the clear is a transfer, the counting a shader's atomics.
    const SyncScope shader{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const SyncScope clear{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    memory_barrier(ctx.cmd(), shader, clear);
    vkCmdFillBuffer(ctx.cmd(), histogram_.handle(), 0, VK_WHOLE_SIZE, 0);
    memory_barrier(ctx.cmd(), clear, shader);
    Image& color = ctx.image("in.color");
    const DescriptorWrite writes[] = {sampled_image(0, color.view(), ctx.nearest_sampler()),
                                      storage_buffer(1, histogram_.handle())};
    dispatch_compute(ctx, "nodes/post/exposure/shaders/histogram.comp", writes, color.desc().width, color.desc().height,
                     std::as_bytes(std::span(&push_, 1)), kHistogramTile);
  }

  void meter(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the histogram pass's atomics, outside the plan's barriers
    const bool history = ctx.has("in.history");
    Push push = push_;
    push.seconds = usable_seconds(ctx.scene().frame_seconds);
    // The executor clears history before the first frame (and a resize makes a new one): 0 EV
    // there is no measurement, so the first frame takes the metered value at once.
    push.restart = history_usable(ctx, "in.history") ? 0u : 1u;
    // Unlinked history: the colour stands in at its binding, and the shader does not read it.
    const VkImageView previous = ctx.image(history ? "in.history" : "in.color").view();
    const DescriptorWrite writes[] = {storage_buffer(0, histogram_.handle()),
                                      sampled_image(1, previous, ctx.nearest_sampler()),
                                      storage_image(2, ctx.image("out.exposure").view())};
    dispatch_compute(ctx, "nodes/post/exposure/shaders/meter.comp", writes, 1, 1, std::as_bytes(std::span(&push, 1)),
                     1);
  }

  Push push_;
  Buffer histogram_;
};

}  // namespace

ExposureSettings exposure_settings(const PlanNode& node) {
  ExposureSettings s;
  s.histogram_min = param_number(node, "histogram_min");
  s.histogram_max = param_number(node, "histogram_max");
  s.low_percent = param_number(node, "low_percent");
  s.high_percent = param_number(node, "high_percent");
  s.compensation = param_number(node, "compensation");
  s.speed_up = param_number(node, "speed_up");
  s.speed_down = param_number(node, "speed_down");
  check_exposure_settings(s, "post.exposure '" + node.id + "'");
  return s;
}

std::unique_ptr<NodeKernel> make_exposure_kernel(const PlanNode& node) {
  return std::make_unique<ExposureKernel>(node);
}

}  // namespace lg
