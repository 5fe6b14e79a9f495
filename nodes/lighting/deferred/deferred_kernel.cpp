#include "nodes/lighting/deferred/deferred_kernel.h"

#include <glm/vec4.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/lighting/deferred/light_buffers.h"
#include "nodes/lighting/deferred/light_culling.h"
#include "nodes/lighting/deferred/local_shadows.h"
#include "nodes/lighting/deferred/shadow_depth_pipeline.h"
#include "nodes/lighting/deferred/shadow_projection.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/light_alpha.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

// One view of a depth pass: a matrix into clip space and the square of the map it draws into.
struct DepthView {
  glm::mat4 clip_from_world;
  glm::uvec2 origin;
  uint32_t size;
};

class DeferredKernel final : public NodeKernel {
 public:
  explicit DeferredKernel(const PlanNode& node)
      : shadow_budget_(static_cast<uint32_t>(param_number(node, "shadow_budget"))),
        atlas_size_(static_cast<uint32_t>(param_number(node, "local_shadow_atlas_size"))),
        area_shadow_samples_(static_cast<uint32_t>(param_number(node, "area_shadow_samples"))),
        cull_lights_(param_bool(node, "cull_lights")),
        area_specular_ltc_(param_string(node, "area_specular") == "ltc") {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "shadows")
      record_shadows(ctx);
    else if (pass == "local_shadows")
      record_local_shadows(ctx);
    else if (pass == "direct")
      record_direct(ctx);
    else if (pass == "area")
      record_area(ctx);
    else if (pass == "emission")
      record_emission(ctx);
    else
      throw std::logic_error("lighting.deferred has no pass '" + pass + "'");
  }

 private:
  // Once per frame, before the frame's first pass of this node: the constants and light lists.
  void prepare(PassContext& ctx) {
    if (prepared_frame_ == ctx.frame_index() && lights_) return;
    prepared_frame_ = ctx.frame_index();
    if (!lights_) {
      lights_.emplace(ctx.gpu(), ctx.node().id);
      draw_blocks_.emplace(ctx.gpu(), ctx.node().id + " draw blocks", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    }
    const SceneView& scene = ctx.scene();
    if (bounds_version_ != scene.version || !bounds_) {
      bounds_ = scene_bounds(scene);
      bounds_version_ = scene.version;
    }
    const int caster = shadow_caster(scene);
    shadow_drawn_ = local_drawn_ = false;
    // The light lists and the shadow budget see only the lights that reach the view.
    const SceneView lights = lights_in_view(scene, cull_lights_);
    local_ = plan_local_shadows(lights, shadow_budget_, atlas_size_);
    LightConstants c{};
    if (caster >= 0) c.shadow_from_world = shadow_from_world(*bounds_, scene.directional_lights[caster].direction);
    lights_->write_lights(lights, caster, local_, c);
    constants_ = c;
    draw_blocks_->write(draw_blocks(draw_constants(scene)));
  }

  void record_shadows(PassContext& ctx) {
    prepare(ctx);
    const SceneView& scene = ctx.scene();
    if (shadow_caster(scene) < 0) return;
    Image& map = ctx.image("tmp.shadow_map");
    const uint32_t size = map.desc().width;
    // Half a texel of normal offset at the map's resolution hides acne on surfaces facing the
    // light; the depth bias covers the slope within one texel of the filter.
    const float world_per_texel = 2.0f * 0.5f * glm::length(bounds_->max - bounds_->min) / float(size);
    constants_.shadow = glm::vec4(1.0f / float(size), 1.0f, 1.5f * world_per_texel, 2.0f / float(size));
    shadow_drawn_ = true;
    draw_depth(ctx, map, {{constants_.shadow_from_world, glm::uvec2(0), size}});
  }

  // Every view of the point, spot and area lights the budget chose, each into its tile of the atlas.
  void record_local_shadows(PassContext& ctx) {
    prepare(ctx);
    std::vector<DepthView> views;
    for (const LocalShadowView& v : local_.views) views.push_back({v.clip_from_world, v.origin, v.size});
    draw_depth(ctx, ctx.image("tmp.local_shadow_atlas"), views);
    constants_.local_shadow = glm::vec4(1.0f, local_shadow_near, float(area_shadow_samples_), 0.0f);
    local_drawn_ = true;
  }

  // Clears `map` and draws every draw's depth into each view's square of it (reversed depth:
  // 0, the clear value, is farthest from the light). Draws whose alpha lets light through
  // (light_alpha_cutoff) go through the alpha-tested pipeline, the others through positions only.
  void draw_depth(PassContext& ctx, Image& map, const std::vector<DepthView>& views) {
    const SceneView& scene = ctx.scene();
    GpuScene& gpu_scene = ctx.gpu_scene();
    VkRenderingAttachmentInfo depth = cleared_attachment(map.view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(map.desc().width, map.desc().height, {}, &depth);
    const Pipeline& opaque = shadow_depth_pipeline(ctx, map.desc().format, false);
    const Pipeline& alpha_tested = shadow_depth_pipeline(ctx, map.desc().format, true);

    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    // Each draw binds its own block (shadow_draw.glsl), an alpha-tested one its texture too.
    for (const DepthView& view : views) {
      const VkViewport viewport{float(view.origin.x), float(view.origin.y), float(view.size), float(view.size), 0, 1};
      const VkRect2D scissor{{int32_t(view.origin.x), int32_t(view.origin.y)}, {view.size, view.size}};
      vkCmdSetViewport(cmd, 0, 1, &viewport);
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      for (uint32_t i = 0; i < scene.draws.size(); ++i) {
        const PbrMaterial& m = scene.material_of(scene.draws[i]);
        const bool tested = light_alpha_cutoff(m) > 0.0f;
        const Pipeline& pipeline = tested ? alpha_tested : opaque;
        DescriptorWrite writes[2] = {draw_block(0, draw_blocks_->handle(), i)};
        if (tested)
          writes[1] = sampled_image(1, gpu_scene.texture(m.base_color_texture.texture).view(),
                                    gpu_scene.sampler(m.base_color_texture.sampling));
        bind_pipeline(ctx.gpu(), cmd, pipeline, std::span(writes, tested ? 2 : 1));
        push_constants(cmd, pipeline, ShadowDrawPush{view.clip_from_world});
        draw_mesh(cmd, gpu_scene.mesh(scene.draws[i].mesh));
      }
    }
    vkCmdEndRendering(cmd);
  }

  // The G-buffer's four surface images at bindings 1 to 4, as surface.glsl declares them.
  void add_gbuffer(PassContext& ctx, std::vector<DescriptorWrite>& writes) {
    for (int c = 0; c < 4; ++c)
      writes.push_back(sampled_image(uint32_t(1 + c), ctx.image("in.gbuffer", c).view(), ctx.nearest_sampler()));
  }

  // The atlas and its views at bindings 14 and 15. Without the local shadow pass (no light casts
  // shadows into it) any depth image binds; local_shadow.x = 0 skips it.
  void add_local_shadow_atlas(PassContext& ctx, std::vector<DescriptorWrite>& writes) {
    Image& atlas = ctx.has("tmp.local_shadow_atlas") ? ctx.image("tmp.local_shadow_atlas") : ctx.image("in.gbuffer", 0);
    writes.push_back(sampled_image(14, atlas.view(), ctx.nearest_sampler()));
    lights_->add_shadow_views(writes);
  }

  void record_direct(PassContext& ctx) {
    prepare(ctx);
    if (!shadow_drawn_) constants_.shadow = glm::vec4(0.0f);
    if (!local_drawn_) constants_.local_shadow = glm::vec4(0.0f);
    Image& color = ctx.image("out.color");
    constants_.camera = camera_constants(ctx.scene().camera, color.desc().width, color.desc().height);
    lights_->constants.write_value(constants_);
    std::vector<DescriptorWrite> writes;
    lights_->add_constants(writes);
    add_gbuffer(ctx, writes);
    writes.push_back(storage_image(5, color.view()));
    // Without a shadow pass (no shadow-casting light) any depth image binds; shadow.y = 0 skips it.
    Image& shadow_map = ctx.has("tmp.shadow_map") ? ctx.image("tmp.shadow_map") : ctx.image("in.gbuffer", 0);
    writes.push_back(sampled_image(10, shadow_map.view(), ctx.nearest_sampler()));
    add_local_shadow_atlas(ctx, writes);
    lights_->add_direct_lists(writes);
    dispatch_compute(ctx, "nodes/lighting/deferred/shaders/direct.comp", writes, color.desc().width,
                     color.desc().height, {}, kTileSize, local_shadows_drawn());
  }

  void record_area(PassContext& ctx) {
    prepare(ctx);
    Image& color = ctx.image("out.color");
    std::vector<DescriptorWrite> writes;
    lights_->add_constants(writes);
    add_gbuffer(ctx, writes);
    writes.push_back(storage_image(5, color.view()));
    add_local_shadow_atlas(ctx, writes);
    lights_->add_area_lists(writes);
    // Constant 1: area_lights.glsl's area_specular_ltc; 5 to 7: whether the frame has spheres,
    // tubes, rectangles (2 to 4 are the reflection capture's, which includes the same file).
    const uint32_t constants[] = {local_drawn_ ? 1u : 0u,
                                  area_specular_ltc_ ? 1u : 0u,
                                  0u,
                                  0u,
                                  0u,
                                  constants_.counts[2] > 0 ? 1u : 0u,
                                  constants_.counts[3] > 0 ? 1u : 0u,
                                  constants_.counts2[0] > 0 ? 1u : 0u};
    dispatch_compute(ctx, "nodes/lighting/deferred/shaders/area.comp", writes, color.desc().width, color.desc().height,
                     {}, kTileSize, constants);
  }

  // Specialization constant 0 of direct.comp and area.comp (shaders/local_shadow_atlas.glsl).
  std::span<const uint32_t> local_shadows_drawn() const {
    static constexpr uint32_t yes = 1, no = 0;
    return {local_drawn_ ? &yes : &no, 1};
  }

  void record_emission(PassContext& ctx) {
    Image& color = ctx.image("out.color");
    const DescriptorWrite writes[] = {
        sampled_image(0, ctx.image("in.gbuffer", gbuffer_emissive).view(), ctx.nearest_sampler()),
        storage_image(1, color.view())};
    dispatch_compute(ctx, "nodes/lighting/deferred/shaders/emission.comp", writes, color.desc().width,
                     color.desc().height);
  }

  static constexpr int gbuffer_emissive = 5;  // the bundle's component (graph/port_type.cpp)

  const uint32_t shadow_budget_, atlas_size_, area_shadow_samples_;
  const bool cull_lights_, area_specular_ltc_;
  std::optional<LightBuffers> lights_;
  std::optional<HostBuffer> draw_blocks_;
  LightConstants constants_{};
  std::optional<Bounds> bounds_;
  uint64_t bounds_version_ = 0;
  uint64_t prepared_frame_ = ~uint64_t{0};
  LocalShadows local_;
  bool shadow_drawn_ = false, local_drawn_ = false;
};

}  // namespace

std::unique_ptr<NodeKernel> make_deferred_kernel(const PlanNode& node) {
  return std::make_unique<DeferredKernel>(node);
}

}  // namespace lg
