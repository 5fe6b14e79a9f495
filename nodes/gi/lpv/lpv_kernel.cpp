#include "nodes/gi/lpv/lpv_kernel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/gi/common/cell_grid.h"
#include "nodes/gi/common/main_light.h"
#include "nodes/gi/common/rebuild_key.h"
#include "nodes/gi/common/voxelize_draws.h"
#include "nodes/gi/lpv/lpv_model.h"
#include "nodes/lighting/deferred/shadow_depth_pipeline.h"
#include "nodes/lighting/deferred/shadow_projection.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFixedRange = 1073741824.0;  // 2^30: the most any fixed-point sum may reach
constexpr double kLobePeak = 1.02332671;      // the largest coefficient of sh_l1_cosine_lobe
// A triangle's blocking in a cell is at most 1 x kLobePeak (lpv_voxelize.comp), its offset at most
// sqrt(3) / 2: 2^16 units a unit keeps 2^15 of them in a cell within an int, which no cell's
// surfaces come near.
constexpr double kOcclusionUnit = 65536.0;

struct Constants {  // shaders/lpv_common.glsl
  glm::vec4 origin_cell;
  glm::ivec4 counts;
  glm::vec4 light;
  glm::vec4 scales;  // x, y: fixed-point scales; z: 1 when a light or the sky was injected (the coverage)
};

struct RsmLight {  // shaders/lpv_rsm.frag
  glm::vec4 direction, irradiance;
};

// Whether the SH this pass reads is the same every frame (is_static_result).
bool static_sh(PassContext& ctx) {
  const Plan& plan = ctx.plan();
  for (const PlanAccess& a : plan.accesses_of(ctx.pass()))
    if (plan.slot_of(a) == "in.sh") return is_static_result(plan, a);
  return false;
}

// lpv_model.h's face table as shaders/lpv_propagate.comp reads it: 30 bases, then 30 lobes.
std::vector<glm::vec4> face_table() {
  std::vector<glm::vec4> out(2 * 6 * kLpvFacesPerDirection);
  for (int d = 0; d < 6; ++d)
    for (int f = 0; f < kLpvFacesPerDirection; ++f) {
      const LpvFace& face = lpv_faces()[d][f];
      const int i = d * kLpvFacesPerDirection + f;
      out[i] = glm::vec4(
          glm::dvec4(face.towards_basis[0], face.towards_basis[1], face.towards_basis[2], face.towards_basis[3]));
      out[30 + i] =
          glm::vec4(glm::dvec4(face.emitted_lobe[0], face.emitted_lobe[1], face.emitted_lobe[2], face.emitted_lobe[3]));
    }
  return out;
}

class LpvKernel final : public NodeKernel, public LpvBuilds {
 public:
  explicit LpvKernel(const PlanNode& node)
      : cells_(int(param_number(node, "grid"))),
        iterations_(int(param_number(node, "iterations"))),
        occlusion_(param_bool(node, "occlusion")),
        k_(resolution_divisor(node)) {
    const glm::vec3 lo = param_float3(node, "box_min"), hi = param_float3(node, "box_max");
    if (lo != hi) {
      if (!glm::all(glm::lessThan(lo, hi)))
        throw std::invalid_argument(node.id + ": box_min must be below box_max on every axis");
      box_ = Bounds{lo, hi};
    }
  }

  uint64_t sky_marches() const override { return sky_marches_; }
  uint64_t sum_builds() const override { return sum_builds_; }

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "rsm")
      record_rsm(ctx);
    else if (pass == "volume")
      record_volume(ctx);
    else if (pass == "upsample")
      upsample(ctx);
    else
      throw std::logic_error("gi.lpv has no pass '" + pass + "'");
  }

 private:
  // Once a frame, at its first pass: the light, the grid, the constants (but the coverage,
  // record_volume's) and the geometry's part of the sky's key, all from this frame's scene
  // (lights and objects may move every frame).
  void prepare(PassContext& ctx) {
    if (prepared_frame_ == ctx.frame_index() && constants_) return;
    prepared_frame_ = ctx.frame_index();
    const SceneView& scene = ctx.scene();
    scene_bounds_ = draws_bounds(scene, ctx.gpu_scene().mesh_bounds());
    grid_ = fit_cell_grid(box_ ? *box_ : *scene_bounds_, cells_);
    allocate(ctx);

    const int light = main_directional_light(scene);
    const uint32_t rsm_size = ctx.image("tmp.rsm_position").desc().width;
    Constants c{};
    c.origin_cell = glm::vec4(grid_.origin, grid_.cell);
    c.counts = glm::ivec4(grid_.counts, int(rsm_size));
    RsmLight l{glm::vec4(0, -1, 0, 0), glm::vec4(0.0f)};
    double scale = 1.0;
    light_present_ = false;
    if (light >= 0) {
      const DirectionalLightData& d = scene.directional_lights[light];
      // shadow_from_world's square: the bounding sphere's diameter across the beam.
      const double radius = std::max(0.5 * glm::length(scene_bounds_->max - scene_bounds_->min), 1e-3);
      const double texel_area = std::pow(2.0 * radius / rsm_size, 2.0);
      const glm::vec3 e = glm::max(d.irradiance, glm::vec3(0.0f));
      const double peak = std::max({e.r, e.g, e.b});
      // A texel's intensity coefficient is at most peak x area / pi x kLobePeak (diffuse colour
      // at most 1); the whole map's at most rsm_size^2 times that.
      const double largest_sum = double(rsm_size) * rsm_size * peak * texel_area / kPi * kLobePeak;
      light_present_ = std::isfinite(largest_sum) && largest_sum > 0.0;
      if (light_present_) scale = kFixedRange / largest_sum;
      c.light = glm::vec4(glm::normalize(d.direction), float(texel_area));
      l = {glm::vec4(glm::normalize(d.direction), 0.0f), glm::vec4(e, 0.0f)};
      shadow_from_world_ = shadow_from_world(*scene_bounds_, d.direction);
    }
    rsm_light_value_ = l;
    c.scales = glm::vec4(float(scale), float(kOcclusionUnit), 0.0f, 0.0f);
    constants_value_ = c;
    if (!constants_) {
      constants_.emplace(ctx.gpu(), ctx.node().id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      rsm_light_.emplace(ctx.gpu(), ctx.node().id + " rsm light", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      draw_blocks_.emplace(ctx.gpu(), ctx.node().id + " draw blocks", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      faces_.emplace(ctx.gpu(), ctx.node().id + " faces", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      faces_->write(face_table());
    }
    rsm_light_->write_value(l);
    const std::vector<DrawConstants> draws = draw_constants(scene);
    draws_->write(draws);
    draw_blocks_->write(draw_blocks(draws));  // the reflective shadow map's (shadow_draw.glsl)
    frame_draws_ = draws;
  }

  // What the sky's march depends on besides the SH: the grid and the geometry. Not the light:
  // the march ignores it.
  std::vector<std::byte> sky_key(const SceneView& scene) const {
    std::vector<std::byte> key;
    append_key(key, &grid_.origin, sizeof(grid_.origin));
    append_key(key, &grid_.cell, sizeof(grid_.cell));
    append_key(key, &grid_.counts, sizeof(grid_.counts));
    append_geometry_key(key, scene, frame_draws_);
    return key;
  }

  // The grids, sized when the counts change (the box of a moving world may change them). The
  // counts, not their product: 16x8x4 and 8x16x4 need the same buffers but not the same images.
  void allocate(PassContext& ctx) {
    if (grid_.counts == allocated_counts_) return;
    const uint64_t cells = grid_.cell_count();
    auto buffer = [&](const char* name, uint64_t bytes_per_cell) {
      return Buffer::dedicated(ctx.gpu(), {.name = ctx.node().id + " " + name, .size = cells * bytes_per_cell});
    };
    light_fixed_ = buffer("injected light", 48);
    occlusion_fixed_ = buffer("injected occlusion", 48);  // lpv_voxelize.comp
    sum_ = buffer("light sum", 48);
    auto image = [&](const std::string& name, VkFormat format) {
      return Image::dedicated(ctx.gpu(), {.name = ctx.node().id + " " + name,
                                          .kind = ImageKind::image3d,
                                          .format = format,
                                          .width = uint32_t(grid_.counts.x),
                                          .height = uint32_t(grid_.counts.y),
                                          .depth = uint32_t(grid_.counts.z),
                                          .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT});
    };
    const char* channels[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
      sum_images_[c] = image(std::string("light sum ") + channels[c], VK_FORMAT_R16G16B16A16_SFLOAT);
      light_[0][c] = image(std::string("light a ") + channels[c], VK_FORMAT_R32G32B32A32_SFLOAT);
      light_[1][c] = image(std::string("light b ") + channels[c], VK_FORMAT_R32G32B32A32_SFLOAT);
      sky_images_[c] = image(std::string("sky ") + channels[c], VK_FORMAT_R16G16B16A16_SFLOAT);
    }
    sky_images_[3] = image("sky openness", VK_FORMAT_R16G16B16A16_SFLOAT);
    occlusion_grid_ = image("occlusion", VK_FORMAT_R32G32B32A32_SFLOAT);
    sky_planes_ = image("sky planes", VK_FORMAT_R32G32B32A32_SFLOAT);
    images_new_ = true;
    allocated_counts_ = grid_.counts;
  }

  void record_rsm(PassContext& ctx) {
    prepare(ctx);
    Image& position = ctx.image("tmp.rsm_position");
    Image& normal = ctx.image("tmp.rsm_normal");
    Image& flux = ctx.image("tmp.rsm_flux");
    Image& depth = ctx.image("tmp.rsm_depth");
    const uint32_t size = position.desc().width;
    const std::array<VkRenderingAttachmentInfo, 3> colors = {
        cleared_attachment(position.view()), cleared_attachment(normal.view()), cleared_attachment(flux.view())};
    VkRenderingAttachmentInfo depth_attachment = cleared_attachment(depth.view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(size, size, colors, &depth_attachment);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    if (light_present_) {
      const Pipeline& pipeline = rsm_pipeline(ctx, position.desc().format, depth.desc().format);
      set_viewport(cmd, size, size);
      const SceneView& scene = ctx.scene();
      for (uint32_t i = 0; i < scene.draws.size(); ++i) {
        const DescriptorWrite writes[] = {draw_block(0, draw_blocks_->handle(), i),
                                          uniform_buffer(1, rsm_light_->handle())};
        bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
        push_constants(cmd, pipeline, ShadowDrawPush{shadow_from_world_});
        draw_mesh(cmd, ctx.gpu_scene().mesh(scene.draws[i].mesh));
      }
    }
    vkCmdEndRendering(cmd);
  }

  // Both sides of every face, as lighting.deferred's shadow map: a wall modelled as one plane
  // reflects on the side the light reaches.
  static const Pipeline& rsm_pipeline(PassContext& ctx, VkFormat color_format, VkFormat depth_format) {
    GraphicsPipelineDesc desc;
    desc.name = ctx.pass().name;
    desc.vertex_shader = node_shader("nodes/gi/lpv/shaders/lpv_rsm.vert");
    desc.fragment_shader = node_shader("nodes/gi/lpv/shaders/lpv_rsm.frag");
    desc.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}, {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
    desc.push_constant_bytes = sizeof(ShadowDrawPush);
    // Exactly the attributes lpv_rsm.vert reads.
    desc.vertex_bindings = {{0, sizeof(GpuVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position)},
                              {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal)},
                              {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, color)}};
    desc.color_formats = {color_format, color_format, color_format};
    desc.depth_format = depth_format;
    desc.depth_test = desc.depth_write = true;
    return ctx.pipelines().graphics(desc);
  }

  // Injection, propagation and the lookup, in the node's own buffers (which the plan does not
  // see, so it could not order separate passes by them).
  void record_volume(PassContext& ctx) {
    prepare(ctx);
    // The sky's light: the environment's SH linked, in a scene with an environment. It lights the
    // grid's box without the sun too, so it covers it.
    sky_ = ctx.has("in.sh") && ctx.scene().has_environment;
    constants_value_.scales.z = light_present_ || sky_ ? 1.0f : 0.0f;
    constants_->write_value(constants_value_);
    // The march is kept while the grid, the geometry and a static SH stay the same (the sky's
    // images then hold it; new images come with new counts, so a new key); the bounce depends on
    // it and goes into the injected light, so it runs with every build of the sum. A frame
    // without the sky forgets the march.
    const bool moving_sky = sky_ && !static_sh(ctx);
    const std::vector<std::byte> grid_and_geometry = sky_key(ctx.scene());
    std::vector<std::byte> key = sky_ ? grid_and_geometry : std::vector<std::byte>{};
    march_sky_ = sky_ && (moving_sky || key != marched_from_);
    marched_from_.swap(key);
    // The sum is kept while the sky's key, the light and the constants stay too (new images come
    // with new counts): the frame then only reads it, and a still scene pays for the lookup alone.
    std::vector<std::byte> built_from = sum_key(grid_and_geometry);
    if (images_new_ || moving_sky || built_from != built_from_) {
      inject(ctx);
      propagate(ctx);
      store(ctx);
      ++sum_builds_;
    }
    built_from_.swap(built_from);
    lookup(ctx);
  }

  // What the sum depends on: the sky's key (the grid, the geometry), the constants (the light's
  // direction and the grid), the light's irradiance and projection, and whether the sky is in it.
  std::vector<std::byte> sum_key(std::vector<std::byte> key) const {
    append_key(key, &constants_value_, sizeof(constants_value_));
    append_key(key, &rsm_light_value_, sizeof(rsm_light_value_));
    append_key(key, &shadow_from_world_, sizeof(shadow_from_world_));
    append_key(key, &sky_, sizeof(sky_));
    return key;
  }

  void inject(PassContext& ctx) {
    VkCommandBuffer cmd = ctx.cmd();
    if (images_new_)
      for (const Image* image : {&sum_images_[0], &sum_images_[1], &sum_images_[2], &light_[0][0], &light_[0][1],
                                 &light_[0][2], &light_[1][0], &light_[1][1], &light_[1][2], &occlusion_grid_,
                                 &sky_planes_, &sky_images_[0], &sky_images_[1], &sky_images_[2], &sky_images_[3]})
        image_barrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
    // Without the sky nothing reads its images (the lookup and the volume output leave them out,
    // kAddSky), so they are not cleared; the next frame with the sky marches them anew.
    images_new_ = false;
    // Last frame's resolve read the fixed-point sums; clear them for this frame's atomics.
    memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                   {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    vkCmdFillBuffer(cmd, light_fixed_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, occlusion_fixed_.handle(), 0, VK_WHOLE_SIZE, 0);
    memory_barrier(cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                   {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
    const uint32_t size = ctx.image("tmp.rsm_position").desc().width;
    const DescriptorWrite inject[] = {uniform_buffer(0, constants_->handle()),
                                      sampled_image(1, ctx.image("tmp.rsm_position").view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("tmp.rsm_normal").view(), ctx.nearest_sampler()),
                                      sampled_image(3, ctx.image("tmp.rsm_flux").view(), ctx.nearest_sampler()),
                                      storage_buffer(4, light_fixed_.handle())};
    // The first step is not blocked (propagate), so one step or no light needs no geometry volume;
    // the sky's light always does.
    if ((occlusion_ && light_present_ && iterations_ > 1) || sky_) voxelize(ctx);
    if (light_present_) dispatch_compute(ctx, "nodes/gi/lpv/shaders/lpv_inject.comp", inject, size, size);
    compute_to_compute_barrier(cmd);
    const DescriptorWrite resolve[] = {uniform_buffer(0, constants_->handle()),
                                       storage_buffer(1, light_fixed_.handle()),
                                       storage_buffer(2, occlusion_fixed_.handle()),
                                       storage_image(3, light_[0][0].view()),
                                       storage_image(4, light_[0][1].view()),
                                       storage_image(5, light_[0][2].view()),
                                       storage_buffer(6, sum_.handle()),
                                       storage_image(7, occlusion_grid_.view()),
                                       storage_image(8, sky_planes_.view())};
    dispatch_cells(ctx, "nodes/gi/lpv/shaders/lpv_resolve.comp", resolve);
    if (march_sky_) add_sky(ctx), ++sky_marches_;
    if (sky_) add_sky_bounce(ctx);
  }

  // The sky's light through the geometry volume into its images (lpv_sky.comp), after the resolve
  // wrote the planes; the lookup's barrier orders it before the lookup reads them.
  void add_sky(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()), general_sampled(ctx, 1, sky_planes_),
                                      storage_buffer(2, ctx.buffer("in.sh").handle()),
                                      storage_image(3, sky_images_[0].view()),
                                      storage_image(4, sky_images_[1].view()),
                                      storage_image(5, sky_images_[2].view()),
                                      storage_image(6, sky_images_[3].view())};
    dispatch_cells(ctx, "nodes/gi/lpv/shaders/lpv_sky.comp", writes);
  }

  // The sky's light the surfaces reflect, into the injected light and the sum (lpv_sky_bounce.comp),
  // after the march wrote the sky's images; the propagation's first barrier orders it before.
  void add_sky_bounce(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());
    const DescriptorWrite writes[] = {
        uniform_buffer(0, constants_->handle()),          storage_buffer(1, occlusion_fixed_.handle()),
        linear_general(ctx, 2, sky_images_[0]),           linear_general(ctx, 3, sky_images_[1]),
        linear_general(ctx, 4, sky_images_[2]),           linear_general(ctx, 5, sky_images_[3]),
        storage_buffer(6, sum_.handle()),                 storage_image(7, light_[0][0].view()),
        storage_image(8, light_[0][1].view()),            storage_image(9, light_[0][2].view())};
    dispatch_cells(ctx, "nodes/gi/lpv/shaders/lpv_sky_bounce.comp", writes);
  }

  // The geometry volume from every draw's triangles (lpv_voxelize.comp).
  void voxelize(PassContext& ctx) {
    voxelize_draws(ctx, "nodes/gi/lpv/shaders/lpv_voxelize.comp", grid_, *constants_, *draws_, occlusion_fixed_);
  }

  void propagate(PassContext& ctx) {
    for (int i = 0; i < iterations_; ++i) {
      compute_to_compute_barrier(ctx.cmd());
      const uint32_t occlude = occlusion_ && i > 0 ? 1u : 0u;
      std::array<Image, 3>&from = light_[i % 2], &to = light_[(i + 1) % 2];
      const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()),  general_sampled(ctx, 1, from[0]),
                                        general_sampled(ctx, 2, from[1]),         general_sampled(ctx, 3, from[2]),
                                        storage_image(4, to[0].view()),           storage_image(5, to[1].view()),
                                        storage_image(6, to[2].view()),           storage_buffer(7, sum_.handle()),
                                        general_sampled(ctx, 8, occlusion_grid_), uniform_buffer(9, faces_->handle())};
      dispatch_cells(ctx, "nodes/gi/lpv/shaders/lpv_propagate.comp", writes, std::as_bytes(std::span(&occlude, 1)));
    }
  }

  // The sum into the 3D images (kept in the GENERAL layout).
  void store(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the sum's last writes; last frame's reads of the images
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()), storage_buffer(1, sum_.handle()),
                                      storage_image(2, sum_images_[0].view()), storage_image(3, sum_images_[1].view()),
                                      storage_image(4, sum_images_[2].view())};
    dispatch_cells(ctx, "nodes/gi/lpv/shaders/lpv_store.comp", writes);
  }

  // The stored sum and the sky per pixel.
  void lookup(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the store's writes

    // At the G-buffer's size: the lookup reconstructs positions at its pixels.
    Image& depth = ctx.image("in.gbuffer", 0);
    camera_->write_value(camera_constants(ctx.scene().camera, depth.desc().width, depth.desc().height));
    Image& target = ctx.image(k_ == 1 ? "out.irradiance" : "tmp.lowres");
    std::vector<DescriptorWrite> writes = {uniform_buffer(0, constants_->handle()),
                                           uniform_buffer(1, camera_->handle()),
                                           sampled_image(2, depth.view(), ctx.nearest_sampler()),
                                           sampled_image(3, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler())};
    for (uint32_t c = 0; c < 3; ++c)
      writes.push_back(sampled_image(4 + c, sum_images_[c].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL));
    writes.push_back(storage_image(7, target.view()));
    for (uint32_t c = 0; c < 4; ++c) writes.push_back(linear_general(ctx, 8 + c, sky_images_[c]));
    // kAddSky: without the sky the lookup skips the sky's four fetches (lavapipe would run both
    // sides of a branch on a uniform; docs/lavapipe-costs.md), its images bound all the same.
    const uint32_t add_sky = sky_ ? 1u : 0u;
    dispatch_compute(ctx, "nodes/gi/lpv/shaders/lpv_lookup.comp", writes, target.desc().width, target.desc().height,
                     std::as_bytes(std::span(&k_, 1)), kTileSize, std::span(&add_sky, 1));
    if (ctx.has("out.volume")) write_volume(ctx, add_sky);
  }

  // The optional volume output (linked or dumped): the sum's and the sky's L0 terms as mean
  // irradiance (lpv_volume.comp), after the store above (its barrier precedes the lookup, which
  // also reads).
  void write_volume(PassContext& ctx, uint32_t add_sky) {
    Image& volume = ctx.image("out.volume");
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()), general_sampled(ctx, 1, sum_images_[0]),
                                      general_sampled(ctx, 2, sum_images_[1]), general_sampled(ctx, 3, sum_images_[2]),
                                      storage_image(4, volume.view()),           general_sampled(ctx, 5, sky_images_[0]),
                                      general_sampled(ctx, 6, sky_images_[1]),   general_sampled(ctx, 7, sky_images_[2]),
                                      general_sampled(ctx, 8, sky_images_[3])};
    const ImageDesc& d = volume.desc();
    dispatch_compute(ctx, "nodes/gi/lpv/shaders/lpv_volume.comp", writes, d.width, d.height * d.depth, {}, kTileSize,
                     std::span(&add_sky, 1));
  }

  // At resolution_scale below 1, the lookup's smaller image to full resolution, guided by depth
  // and normals (gi.irradiance_volume's upsample); at 1 the lookup wrote the output itself.
  void upsample(PassContext& ctx) {
    if (k_ == 1) return;
    Image& low = ctx.image("tmp.lowres");
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(3, ctx.image("out.irradiance").view())};
    dispatch_compute(ctx, "nodes/gi/irradiance_volume/shaders/upsample.comp", writes, low.desc().width,
                     low.desc().height, std::as_bytes(std::span(&k_, 1)));
  }

  // A grid image read with texelFetch (kept in the GENERAL layout, as it is also written).
  static DescriptorWrite general_sampled(PassContext& ctx, uint32_t binding, Image& image) {
    return sampled_image(binding, image.view(), ctx.nearest_sampler(), VK_IMAGE_LAYOUT_GENERAL);
  }

  // A grid image filtered by the sampler (kept in the GENERAL layout, as it is also written).
  static DescriptorWrite linear_general(PassContext& ctx, uint32_t binding, Image& image) {
    return sampled_image(binding, image.view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL);
  }

  // One invocation per cell: x across the grid, y down its rows of every slice (lpv_common.glsl).
  void dispatch_cells(PassContext& ctx, std::string_view shader, std::span<const DescriptorWrite> writes,
                      std::span<const std::byte> push = {}) {
    dispatch_compute(ctx, shader, writes, uint32_t(grid_.counts.x), uint32_t(grid_.counts.y * grid_.counts.z), push);
  }

  const int cells_, iterations_;
  const bool occlusion_;
  const int32_t k_;  // the G-buffer's resolution over the lookup's: 1 / resolution_scale
  std::optional<Bounds> box_, scene_bounds_;
  std::optional<uint64_t> prepared_frame_;
  CellGrid grid_;
  glm::mat4 shadow_from_world_{1.0f};
  bool light_present_ = false;
  bool sky_ = false;          // the sky's light added (record_volume)
  bool march_sky_ = false;    // this frame marches the sky (record_volume)
  uint64_t sky_marches_ = 0;  // frames that marched it (LpvBuilds)
  uint64_t sum_builds_ = 0;   // frames that built the sum (LpvBuilds)
  // What the sky's march depends on this frame (prepare, record_volume), and what the sky's
  // images were last marched from (empty: not marched, or the sky absent since).
  std::vector<DrawConstants> frame_draws_;  // this frame's (prepare())
  std::vector<std::byte> marched_from_;     // sky_key() of the last march; empty without the sky
  std::vector<std::byte> built_from_;       // sum_key() of the last frame
  Constants constants_value_{};  // as prepare() made them; record_volume adds the coverage and writes them
  RsmLight rsm_light_value_{};   // as prepare() wrote it
  glm::ivec3 allocated_counts_{0};  // none yet
  std::optional<HostBuffer> constants_, rsm_light_, draws_, draw_blocks_, camera_, faces_;
  Buffer light_fixed_, occlusion_fixed_, sum_;
  // Per channel: the light each step sends on, in turn (rgba32f, lpv_outflow's form), and the sum
  // the lookup filters (rgba16f radiance); the occlusion.
  std::array<std::array<Image, 3>, 2> light_;
  std::array<Image, 3> sum_images_;
  Image occlusion_grid_;
  Image sky_planes_;  // per cell its surfaces' mean plane, for the sky's march (lpv_resolve.comp)
  // The sky's light per channel (SH L1 radiance x openness, rgba16f) and the openness (r).
  std::array<Image, 4> sky_images_;
  bool images_new_ = false;  // not yet in the GENERAL layout
};

}  // namespace

std::unique_ptr<NodeKernel> make_lpv_kernel(const PlanNode& node) {
  return std::make_unique<LpvKernel>(node);
}

}  // namespace lg
