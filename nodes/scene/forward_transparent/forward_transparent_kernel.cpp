#include "nodes/scene/forward_transparent/forward_transparent_kernel.h"

#include <optional>
#include <stdexcept>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/lighting/deferred/light_buffers.h"
#include "nodes/scene/forward_transparent/blend_order.h"
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

struct Settings {  // shaders/forward.frag
  uint32_t flags;  // 1: image-based light, 2: its diffuse from SH
  float intensity;
};

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
    LightConstants constants{};
    lights_->write_lights(scene, -1, no_local_shadows(scene), constants);
    constants.camera = camera_constants(scene.camera, w, h);
    lights_->constants.write_value(constants);
    draws_->write(draw_constants(scene));
    // Image-based light as lighting.ibl gives it, which a scene without an environment bypasses.
    const Settings settings{(scene.has_environment ? 1u : 0u) | (diffuse_from_sh_ ? 2u : 0u), intensity_};
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
  // What every draw binds (forward.frag's bindings but the material's textures).
  // Where an input is unused, any resource of its kind binds: the settings' flags skip it.
  std::vector<DescriptorWrite> shared_writes(PassContext& ctx) {
    Image& depth = ctx.image("in.gbuffer", 0);
    Image& specular = ctx.image("in.specular");
    std::vector<DescriptorWrite> writes;
    lights_->add_constants(writes);
    writes.push_back(storage_buffer(1, draws_->handle()));
    writes.push_back(storage_buffer(6, ctx.has("in.sh") ? ctx.buffer("in.sh").handle() : draws_->handle()));
    writes.push_back(sampled_image(7, (ctx.has("in.irradiance") ? ctx.image("in.irradiance") : specular).view(),
                                   ctx.linear_sampler()));
    writes.push_back(sampled_image(8, specular.view(), ctx.linear_sampler()));
    writes.push_back(sampled_image(9, ctx.image("in.brdf_lut").view(), ctx.linear_sampler()));
    // The shadow map and the local shadow atlas are not drawn here (the constants say so).
    writes.push_back(sampled_image(10, depth.view(), ctx.nearest_sampler()));
    writes.push_back(sampled_image(14, depth.view(), ctx.nearest_sampler()));
    lights_->add_direct_lists(writes);
    lights_->add_shadow_views(writes);
    lights_->add_area_lists(writes);
    writes.push_back(sampled_image(19, depth.view(), ctx.nearest_sampler()));
    writes.push_back(uniform_buffer(20, settings_->handle()));
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

  // The G-buffer's textured vertex stage, forward.frag, premultiplied "over" blending; back
  // faces culled unless the material is double-sided.
  const Pipeline& draw_pipeline(PassContext& ctx, VkFormat format, bool double_sided) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader("nodes/scene/gbuffer/shaders/gbuffer.vert");
    desc.fragment_shader = node_shader("nodes/scene/forward_transparent/shaders/forward.frag");
    for (uint32_t b = 0; b <= 21; ++b) desc.bindings.push_back({b, binding_type(b)});
    desc.push_constant_bytes = sizeof(uint32_t);
    use_gpu_vertices(desc, true);
    desc.cull = double_sided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    desc.color_formats = {format};
    desc.blend = Blend::premultiplied;
    return ctx.pipelines().graphics(desc);
  }

  // forward.frag's bindings: constants 0 and settings 20 uniform; draws 1, SH 6 and the light
  // lists (11 to 13, 15 to 18) storage buffers; the rest sampled images (the material's
  // textures at material_texture_bindings among them).
  static VkDescriptorType binding_type(uint32_t b) {
    if (b == 0 || b == 20) return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (b == 1 || b == 6 || (b >= 11 && b <= 13) || (b >= 15 && b <= 18)) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
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
