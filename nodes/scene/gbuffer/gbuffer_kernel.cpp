#include "nodes/scene/gbuffer/gbuffer_kernel.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "nodes/scene/gbuffer/material_textures.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/frustum.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

class GbufferKernel final : public NodeKernel {
 public:
  explicit GbufferKernel(const PlanNode& node)
      : cull_backfaces_(param_bool(node, "cull_backfaces")), frustum_culling_(param_bool(node, "frustum_culling")) {}

  void record(PassContext& ctx) override {
    Image* targets[gbuffer_targets];
    for (int c = 0; c < gbuffer_targets; ++c) targets[c] = &ctx.image("out.gbuffer", c);
    const uint32_t w = targets[0]->desc().width, h = targets[0]->desc().height;
    const SceneView& scene = ctx.scene();
    if (!camera_) {
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      draw_blocks_.emplace(ctx.gpu(), ctx.node().id + " draw blocks", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    }
    camera_->write_value(camera_constants(scene.camera, w, h));
    const std::vector<DrawConstants> constants = draw_constants(scene);
    draws_->write(constants);
    draw_blocks_->write(draw_blocks(constants));

    VkRenderingAttachmentInfo colors[gbuffer_targets - 1];
    for (int c = 1; c < gbuffer_targets; ++c) colors[c - 1] = cleared_attachment(targets[c]->view(), {});
    VkRenderingAttachmentInfo depth =
        cleared_attachment(targets[0]->view(), {.depthStencil = {0.0f, 0}});  // reversed Z: 0 is infinity
    const VkRenderingInfo rendering = rendering_info(w, h, colors, &depth);

    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    set_viewport(cmd, w, h);
    GpuScene& gpu_scene = ctx.gpu_scene();
    const Pipeline* variants[3][2] = {};  // [Variant][double-sided], looked up once a frame
    // Draws outside the camera's frustum are not submitted; `i` still indexes the draw buffer.
    std::vector<uint32_t> drawn(scene.draws.size());
    std::iota(drawn.begin(), drawn.end(), 0u);
    if (frustum_culling_) drawn = visible_draws(scene, gpu_scene.mesh_bounds(), view_frustum(scene.camera));
    for (uint32_t i : drawn) {
      const DrawItem& d = scene.draws[i];
      const PbrMaterial& m = scene.material_of(d);
      if (m.alpha_mode == AlphaMode::blend) continue;  // scene.forward_transparent draws it
      std::vector<DescriptorWrite> writes = {uniform_buffer(0, camera_->handle()), storage_buffer(1, draws_->handle()),
                                             draw_block(6, draw_blocks_->handle(), i)};
      add_material_textures(gpu_scene, m, writes);
      Variant kind = m.alpha_mode == AlphaMode::mask ? masked : textured;
      const auto maps = material_maps(m);
      if (kind == textured && scene.mesh_of(d).colors.empty() &&
          std::all_of(maps.begin(), maps.end(), [](const TextureRef* t) { return t->texture < 0; }))
        kind = plain;
      const Pipeline*& variant = variants[kind][m.double_sided];
      if (!variant) variant = &pipeline(ctx, targets, kind, m.double_sided);
      const Pipeline& pipeline = *variant;
      bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, gpu_scene.mesh(d.mesh));
    }
    vkCmdEndRendering(cmd);
  }

 private:
  // Depth, then the colour targets: normal, albedo, material, motion, emissive (graph/port_type.cpp).
  static constexpr int gbuffer_targets = 6;

  // Shader variants (gbuffer_surface.glsl): factors only for draws without textures or vertex
  // colours (fewer inputs to interpolate), the whole material, or the whole material with the
  // alpha test.
  enum Variant { plain, textured, masked };

  // One of six pipelines, cached by the pipeline cache: a Variant, culling back faces as the
  // node's param says or (double-sided materials) not at all.
  const Pipeline& pipeline(PassContext& ctx, Image* const* targets, Variant kind, bool double_sided) {
    static constexpr const char* fragment_shaders[] = {"nodes/scene/gbuffer/shaders/gbuffer_plain.frag",
                                                       "nodes/scene/gbuffer/shaders/gbuffer.frag",
                                                       "nodes/scene/gbuffer/shaders/gbuffer_masked.frag"};
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader(kind == plain ? "nodes/scene/gbuffer/shaders/gbuffer_plain.vert"
                                                   : "nodes/scene/gbuffer/shaders/gbuffer_maps.vert");
    desc.fragment_shader = node_shader(fragment_shaders[kind]);
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                     {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                     {6, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    for (uint32_t binding : material_texture_bindings)
      desc.bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
    desc.push_constant_bytes = sizeof(uint32_t);
    use_gpu_vertices(desc, kind != plain);
    // Meshes wind counter-clockwise seen from outside; the projection flips y for Vulkan, which
    // keeps that winding counter-clockwise in framebuffer terms: the pipeline's default front face.
    desc.cull = cull_backfaces_ && !double_sided ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    for (int c = 1; c < gbuffer_targets; ++c) desc.color_formats.push_back(targets[c]->desc().format);
    desc.depth_format = targets[0]->desc().format;
    desc.depth_test = desc.depth_write = true;
    return ctx.pipelines().graphics(desc);
  }

  bool cull_backfaces_, frustum_culling_;
  std::optional<HostBuffer> camera_, draws_, draw_blocks_;
};

}  // namespace

std::unique_ptr<NodeKernel> make_gbuffer_kernel(const PlanNode& node) {
  return std::make_unique<GbufferKernel>(node);
}

}  // namespace lg
