#include "nodes/env/brdf_lut/brdf_lut_kernel.h"

#include <algorithm>

#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"

namespace lg {
namespace {

class BrdfLutKernel final : public NodeKernel {
 public:
  explicit BrdfLutKernel(const PlanNode& node) : samples_(uint32_t(param_number(node, "samples"))) {}

  void record(PassContext& ctx) override {
    record_brdf_lut(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, samples_, ctx.image("out.lut"));
  }

 private:
  uint32_t samples_;
};

}  // namespace

void record_brdf_lut(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                     uint32_t samples, Image& lut) {
  const uint32_t push = std::clamp(samples, 1u, kMaxLutSamples);
  const Pipeline& pipeline = pipelines.compute(
      {name, node_shader("nodes/env/brdf_lut/shaders/dfg.comp"), {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, sizeof push});
  const DescriptorWrite writes[] = {storage_image(0, lut.view())};
  bind_pipeline(gpu, cmd, pipeline, writes);
  push_constants(cmd, pipeline, push);
  dispatch_texels(cmd, lut.desc().width, lut.desc().height);
}

std::unique_ptr<NodeKernel> make_brdf_lut_kernel(const PlanNode& node) {
  return std::make_unique<BrdfLutKernel>(node);
}

}  // namespace lg
