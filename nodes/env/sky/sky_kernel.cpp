#include "nodes/env/sky/sky_kernel.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

constexpr int kSunPoints = 64;  // nodes/env/sky/shaders/sky.comp
constexpr uint32_t kGroup = 8;

struct Push {  // nodes/env/sky/shaders/sky.comp
  glm::vec4 sun, sky_sun, perez_lum, perez_x, perez_y, perez_e, ground;
  float zenith_scale[3];
  int32_t subsamples;
};

Push make_push(const SkyModel& m) {
  Push p{};
  p.sun = glm::vec4(glm::vec3(m.sun), float(m.sun_radiance * sun_solid_angle() / kSunPoints));
  p.sky_sun = glm::vec4(glm::vec3(m.sky_sun), float(kSunAngularRadius));
  glm::vec4* abcd[3] = {&p.perez_lum, &p.perez_x, &p.perez_y};
  for (int c = 0; c < 3; ++c) {
    *abcd[c] = glm::vec4(float(m.perez[c][0]), float(m.perez[c][1]), float(m.perez[c][2]), float(m.perez[c][3]));
    p.perez_e[c] = float(m.perez[c][4]);
    p.zenith_scale[c] = float(m.zenith_scale[c]);
  }
  p.ground = glm::vec4(glm::vec3(m.ground), 0.0f);
  return p;
}

class SkyKernel final : public NodeKernel {
 public:
  explicit SkyKernel(const PlanNode& node)
      : params_{glm::dvec3(param_float3(node, "sun_direction")), param_number(node, "sun_intensity"),
                param_number(node, "turbidity")},
        turn_speed_(glm::radians(param_number(node, "sun_turn_speed"))) {}

  // A turning sun is recorded every frame (the plan does not cache the node then), each frame's
  // sun turned about +Y by the time since the first; the scene's frame time is its step.
  void record(PassContext& ctx) override {
    SkyParams params = params_;
    if (turn_speed_ != 0.0) {
      if (ctx.frame_index() == 0) seconds_ = 0.0;
      params.sun_direction = sun_turned(params.sun_direction, turn_speed_ * seconds_);
      seconds_ += ctx.scene().frame_seconds;
    }
    record_sky(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, make_sky_model(params), ctx.image("out.cube"));
  }

 private:
  SkyParams params_;
  double turn_speed_;     // radians per second about +Y
  double seconds_ = 0.0;  // since the first frame
};

}  // namespace

glm::dvec3 sun_turned(const glm::dvec3& direction, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return {c * direction.x + s * direction.z, direction.y, -s * direction.x + c * direction.z};
}

void record_sky(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                const SkyModel& model, Image& cube) {
  const Pipeline& pipeline = pipelines.compute(
      {name, node_shader("nodes/env/sky/shaders/sky.comp"), {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof(Push)});
  Push push = make_push(model);
  for (uint32_t mip = 0; mip < cube.desc().mips; ++mip) {
    const uint32_t size = std::max(1u, cube.desc().width >> mip);
    // A texel of mip m spans 2^m texels of mip 0: average the sky over up to 8x8 points of it.
    push.subsamples = int32_t(std::min(1u << std::min(mip, 3u), 8u));
    const DescriptorWrite writes[] = {
        storage_image(0, cube.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1}))};
    bind_pipeline(gpu, cmd, pipeline, writes);
    push_constants(cmd, pipeline, push);
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
}

std::unique_ptr<NodeKernel> make_sky_kernel(const PlanNode& node) {
  return std::make_unique<SkyKernel>(node);
}

}  // namespace lg
