#include "nodes/scene/gbuffer/gbuffer_kernel.h"

#include <optional>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

class GbufferKernel final : public NodeKernel {
 public:
  explicit GbufferKernel(const PlanNode& node) : cull_backfaces_(param_bool(node, "cull_backfaces")) {}

  void record(PassContext& ctx) override {
    Image* targets[5];
    for (int c = 0; c < 5; ++c) targets[c] = &ctx.image("out.gbuffer", c);  // depth, normal, albedo, material, motion
    const uint32_t w = targets[0]->desc().width, h = targets[0]->desc().height;
    const SceneView& scene = ctx.scene();
    if (!camera_) {
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    camera_->write_value(camera_constants(scene.camera, w, h));
    draws_->write(draw_constants(scene));

    VkRenderingAttachmentInfo colors[4];
    for (int c = 0; c < 4; ++c) colors[c] = cleared_attachment(targets[c + 1]->view(), {});
    VkRenderingAttachmentInfo depth =
        cleared_attachment(targets[0]->view(), {.depthStencil = {0.0f, 0}});  // reversed Z: 0 is infinity
    const VkRenderingInfo rendering = rendering_info(w, h, colors, &depth);

    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    const Pipeline& pipeline = this->pipeline(ctx, targets);
    set_viewport(cmd, w, h);
    GpuScene& gpu_scene = ctx.gpu_scene();
    for (uint32_t i = 0; i < scene.draws.size(); ++i) {
      const DrawItem& d = scene.draws[i];
      const int texture = scene.material_of(d).base_color_texture.texture;
      Image& base_color = texture >= 0 ? gpu_scene.texture(texture) : gpu_scene.white_texture();
      const DescriptorWrite writes[] = {uniform_buffer(0, camera_->handle()), storage_buffer(1, draws_->handle()),
                                        sampled_image(2, base_color.view(), ctx.linear_sampler())};
      bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, gpu_scene.mesh(d.mesh));
    }
    vkCmdEndRendering(cmd);
  }

 private:
  const Pipeline& pipeline(PassContext& ctx, Image* const* targets) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader("nodes/scene/gbuffer/shaders/gbuffer.vert");
    desc.fragment_shader = node_shader("nodes/scene/gbuffer/shaders/gbuffer.frag");
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                     {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
    desc.push_constant_bytes = sizeof(uint32_t);
    use_gpu_vertices(desc);
    // Meshes wind counter-clockwise seen from outside; the projection flips y for Vulkan, which
    // keeps that winding counter-clockwise in framebuffer terms: the pipeline's default front face.
    desc.cull = cull_backfaces_ ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    for (int c = 1; c < 5; ++c) desc.color_formats.push_back(targets[c]->desc().format);
    desc.depth_format = targets[0]->desc().format;
    desc.depth_test = desc.depth_write = true;
    return ctx.pipelines().graphics(desc);
  }

  bool cull_backfaces_;
  std::optional<HostBuffer> camera_, draws_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_gbuffer_kernel(const PlanNode& node) {
  return std::make_unique<GbufferKernel>(node);
}

}  // namespace lg
