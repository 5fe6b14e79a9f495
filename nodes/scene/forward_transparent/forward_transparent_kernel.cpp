#include "nodes/scene/forward_transparent/forward_transparent_kernel.h"

#include <optional>
#include <stdexcept>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/lighting/deferred/light_buffers.h"
#include "nodes/lighting/deferred/light_culling.h"
#include "nodes/scene/forward_transparent/blend_order.h"
#include "nodes/scene/forward_transparent/forward_bindings.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "nodes/scene/gbuffer/material_textures.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

class ForwardTransparentKernel final : public NodeKernel {
 public:
  explicit ForwardTransparentKernel(const PlanNode& node)
      : diffuse_from_sh_(param_string(node, "diffuse_source") == "sh"),
        intensity_(float(param_number(node, "intensity"))) {}

  void record(PassContext& ctx) override {
    Image& color = ctx.image("out.color");
    const uint32_t w = color.desc().width, h = color.desc().height;
    const SceneView& scene = ctx.scene();
    const char* diffuse_input = diffuse_from_sh_ ? "in.sh" : "in.irradiance";
    if (!ctx.has(diffuse_input))
      throw std::runtime_error(ctx.node().id + ": diffuse_source '" + (diffuse_from_sh_ ? "sh" : "irradiance_map") +
                               "' needs its input '" + (diffuse_input + 3) + "' linked");
    if (!lights_) {
      lights_.emplace(ctx.gpu(), ctx.node().id);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      settings_.emplace(ctx.gpu(), ctx.node().id + " settings", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    }
    if (centers_version_ != scene.version || centers_.size() != scene.meshes.size()) {
      centers_ = mesh_centers(scene);
      centers_version_ = scene.version;
    }
    // No shadow map and no local shadow views: the constants' zeros say none was drawn.
    // The lights that reach the view, as lighting.deferred shades them (light_culling.h).
    const SceneView lights = lights_in_view(scene);
    LightConstants constants{};
    lights_->write_lights(lights, -1, no_local_shadows(lights), constants);
    constants.camera = camera_constants(scene.camera, w, h);
    lights_->constants.write_value(constants);
    draws_->write(draw_constants(scene));
    // Image-based light as lighting.ibl gives it, which a scene without an environment bypasses.
    const ForwardSettings settings{(scene.has_environment ? 1u : 0u) | (diffuse_from_sh_ ? 2u : 0u), intensity_};
    settings_->write_value(settings);

    VkRenderingAttachmentInfo target = cleared_attachment(color.view());
    target.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // the copy below covers every texel
    const VkRenderingInfo rendering = rendering_info(w, h, {&target, 1});
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    set_viewport(cmd, w, h);
    const Pipeline& copy = copy_pipeline(ctx, color.desc().format);
    const DescriptorWrite copy_writes[] = {sampled_image(0, ctx.image("in.color").view(), ctx.nearest_sampler())};
    bind_pipeline(ctx.gpu(), cmd, copy, copy_writes);
    vkCmdDraw(cmd, 3, 1, 0, 0);

    std::vector<DescriptorWrite> writes = shared_writes(ctx);
    GpuScene& gpu_scene = ctx.gpu_scene();
    for (uint32_t i : blend_draws_back_to_front(scene, centers_)) {
      const DrawItem& d = scene.draws[i];
      const PbrMaterial& m = scene.material_of(d);
      writes.resize(shared_write_count_);
      add_material_textures(gpu_scene, m, writes);
      const Pipeline& pipeline = draw_pipeline(ctx, color.desc().format, m.double_sided);
      bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, gpu_scene.mesh(d.mesh));
    }
    vkCmdEndRendering(cmd);
  }

 private:
  // What every draw binds (forward.frag's bindings but the material's textures). Where an input
  // is unused, any resource of its kind binds: the settings' flags skip it.
  std::vector<DescriptorWrite> shared_writes(PassContext& ctx) {
    Image& specular = ctx.image("in.specular");
    const ForwardResources resources{
        .sh = ctx.has("in.sh") ? ctx.buffer("in.sh").handle() : draws_->handle(),
        .irradiance = (ctx.has("in.irradiance") ? ctx.image("in.irradiance") : specular).view(),
        .specular = specular.view(),
        .brdf_lut = ctx.image("in.brdf_lut").view(),
        .placeholder_2d = ctx.image("in.gbuffer", 0).view(),  // also forward.frag's scene depth at 19
        .linear = ctx.linear_sampler(),
        .nearest = ctx.nearest_sampler()};
    std::vector<DescriptorWrite> writes = forward_writes(*lights_, draws_->handle(), settings_->handle(), resources);
    shared_write_count_ = writes.size();
    return writes;
  }

  const Pipeline& copy_pipeline(PassContext& ctx, VkFormat format) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name + " copy";
    desc.vertex_shader = node_shader("nodes/scene/forward_transparent/shaders/copy.vert");
    desc.fragment_shader = node_shader("nodes/scene/forward_transparent/shaders/copy.frag");
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
    desc.color_formats = {format};
    return ctx.pipelines().graphics(desc);
  }

  // forward_pipeline_desc() with forward.frag and premultiplied "over" blending.
  const Pipeline& draw_pipeline(PassContext& ctx, VkFormat format, bool double_sided) {
    GraphicsPipelineDesc desc = forward_pipeline_desc(
        ctx.pass().name, node_shader("nodes/scene/forward_transparent/shaders/forward.frag"), format, double_sided);
    desc.blend = Blend::premultiplied;
    return ctx.pipelines().graphics(desc);
  }

  const bool diffuse_from_sh_;
  const float intensity_;
  std::optional<LightBuffers> lights_;
  std::optional<HostBuffer> draws_, settings_;
  std::vector<glm::vec3> centers_;
  uint64_t centers_version_ = ~uint64_t{0};
  size_t shared_write_count_ = 0;
};

}  // namespace

std::unique_ptr<NodeKernel> make_forward_transparent_kernel(const PlanNode& node) {
  return std::make_unique<ForwardTransparentKernel>(node);
}

}  // namespace lg
