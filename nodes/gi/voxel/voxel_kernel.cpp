#include "nodes/gi/voxel/voxel_kernel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <cstddef>
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
#include "nodes/gi/common/cell_grid.h"
#include "nodes/gi/common/main_light.h"
#include "nodes/gi/common/rebuild_key.h"
#include "nodes/gi/common/voxelize_draws.h"
#include "nodes/gi/voxel/voxel_local_lights.h"
#include "nodes/lighting/deferred/shadow_depth_pipeline.h"
#include "nodes/lighting/deferred/shadow_projection.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/image_copy.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/scene/scene_view.h"

namespace lg {
namespace {

constexpr uint64_t kGridBytesPerVoxel = 14 * sizeof(int32_t);  // voxel_common.glsl's LG_VOXEL_INTS

struct Constants {  // shaders/voxel_common.glsl
  glm::vec4 origin_cell;
  glm::ivec4 counts;
  glm::vec4 light;
  glm::vec4 irradiance;
  glm::mat4 shadow_from_world;
  glm::ivec4 chain;
  glm::ivec4 sources;
};

// The second injection's push (shaders/voxel_inject.comp): what it adds to the sun's light.
constexpr int32_t kInjectSky = 1, kInjectLocalLights = 2, kInjectBounce = 4;

// The access of this node's pass `pass` to `slot`, or null (an optional input unlinked): the
// kernel's first pass of a frame (the shadow's) decides for the volume pass.
const PlanAccess* node_access(PassContext& ctx, std::string_view pass, std::string_view slot) {
  const Plan& plan = ctx.plan();
  for (const PlanPass& p : plan.passes) {
    if (p.node != ctx.pass().node || p.pass != pass) continue;
    for (const PlanAccess& a : plan.accesses_of(p))
      if (plan.slot_of(a) == slot) return &a;
  }
  return nullptr;
}

// Whether another node's pass, or the file's outputs, read what this node writes to its output
// `slot` (an output nothing reads need not be computed), or the plan keeps every output (a dump).
bool output_read(PassContext& ctx, std::string_view slot) {
  const Plan& plan = ctx.plan();
  if (plan.keeps_every_output) return true;
  const int self = ctx.pass().node;
  int resource = -1;
  for (const PlanPass& p : plan.passes)
    if (p.node == self)
      for (const PlanAccess& a : plan.accesses_of(p))
        if (plan.slot_of(a) == slot) resource = a.resource;
  if (resource < 0) return false;
  for (const PlanOutput& o : plan.outputs)
    if (std::find(o.resources.begin(), o.resources.end(), resource) != o.resources.end()) return true;
  for (const PlanPass& p : plan.passes)
    if (p.node != self)
      for (const PlanAccess& a : plan.accesses_of(p))
        if (a.resource == resource) return true;
  return false;
}

class VoxelKernel final : public NodeKernel {
 public:
  explicit VoxelKernel(const PlanNode& node)
      : resolution_(int(param_number(node, "resolution"))),
        ao_distance_(float(param_number(node, "ao_distance"))),
        bounces_(int(param_number(node, "bounces"))),
        k_(resolution_divisor(node)) {}

  void record(PassContext& ctx) override {
    const std::string& pass = ctx.pass().pass;
    if (pass == "shadow")
      record_shadow(ctx);
    else if (pass == "volume")
      record_volume(ctx);
    else if (pass == "upsample")
      upsample(ctx);
    else
      throw std::logic_error("gi.voxel has no pass '" + pass + "'");
  }

 private:
  // Whether the plan reads out.specular: fixed for the kernel's plan, found at the first pass
  // that asks.
  bool specular_read(PassContext& ctx) {
    if (!specular_read_) specular_read_ = output_read(ctx, "out.specular");
    return *specular_read_;
  }

  // Once a frame, at its first pass: the light, the grid and the constants, all from this
  // frame's scene (lights and objects may move every frame).
  void prepare(PassContext& ctx) {
    if (prepared_frame_ == ctx.frame_index() && constants_) return;
    prepared_frame_ = ctx.frame_index();
    const SceneView& scene = ctx.scene();
    const Bounds bounds = draws_bounds(scene, ctx.gpu_scene().mesh_bounds());
    grid_ = fit_power_of_two_grid(bounds, resolution_);
    allocate(ctx);

    Constants c{};
    c.origin_cell = glm::vec4(grid_.origin, grid_.cell);
    c.counts = glm::ivec4(grid_.counts, int(levels_));
    c.chain = glm::ivec4(doubled_axis_, 0, 0, 0);
    c.light = glm::vec4(0, -1, 0, 0);
    c.irradiance = glm::vec4(0.0f, 0.0f, 0.0f, ao_distance_);
    const int light = main_directional_light(scene);
    light_present_ = light >= 0;
    if (light_present_) {
      const DirectionalLightData& d = scene.directional_lights[light];
      const glm::vec3 direction = glm::normalize(d.direction);
      c.light = glm::vec4(direction, 1.0f);
      c.irradiance = glm::vec4(glm::max(d.irradiance, glm::vec3(0.0f)), ao_distance_);
      c.shadow_from_world = shadow_from_world(bounds, direction);
    }
    shadow_from_world_ = c.shadow_from_world;
    const PlanAccess* sh = node_access(ctx, "volume", "in.sh");
    sky_ = sh && scene.has_environment;
    local_lights_ = voxel_local_lights(scene);
    c.sources = glm::ivec4(light_present_ ? 1 : 0, sky_ ? 1 : 0, local_lights_.count,
                           light_present_ || sky_ || local_lights_.count > 0 ? 1 : 0);
    const std::vector<DrawConstants> draws = draw_constants(scene);
    // The volume is rebuilt only when what it is made of changed: the grid and the light (the
    // constants), the local lights, the geometry, or the sky's SH where it is not a static
    // result. So the frame something moves in rebuilds, and a static scene pays for the cones
    // alone.
    std::vector<std::byte> key;
    append_key(key, &c, sizeof(c));
    append_key(key, local_lights_.lights.data(), local_lights_.count * sizeof(VoxelLocalLight));  // not the padding
    append_geometry_key(key, scene, draws);
    rebuild_ = images_new_ || key != built_from_ || (sky_ && !is_static_result(ctx.plan(), *sh));
    built_from_ = std::move(key);
    if (!constants_) {
      constants_.emplace(ctx.gpu(), ctx.node().id + " constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      draws_.emplace(ctx.gpu(), ctx.node().id + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      draw_blocks_.emplace(ctx.gpu(), ctx.node().id + " draw blocks", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      lights_.emplace(ctx.gpu(), ctx.node().id + " local lights", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      no_sh_.emplace(ctx.gpu(), ctx.node().id + " no SH", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      no_sh_->write(std::vector<float>(4, 0.0f));
    }
    constants_->write_value(c);
    draws_->write(draws);
    draw_blocks_->write(draw_blocks(draws));  // the shadow pass's (shadow_depth_pipeline.h)
    lights_->write_value(local_lights_.lights);
  }

  // The sums and the chain, sized when the counts change (the box of a moving world may change
  // them).
  void allocate(PassContext& ctx) {
    if (grid_.counts == allocated_counts_) return;
    grid_sums_ = Buffer::dedicated(
        ctx.gpu(), {.name = ctx.node().id + " voxel sums", .size = grid_.cell_count() * kGridBytesPerVoxel});
    const int longest = std::max({grid_.counts.x, grid_.counts.y, grid_.counts.z});
    levels_ = uint32_t(std::bit_width(unsigned(longest)));  // down to one voxel
    auto image = [&](const std::string& name, glm::ivec3 counts, uint32_t mips) {
      return Image::dedicated(ctx.gpu(), {.name = ctx.node().id + " " + name,
                                          .kind = ImageKind::image3d,
                                          .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                          .width = uint32_t(counts.x),
                                          .height = uint32_t(counts.y),
                                          .depth = uint32_t(counts.z),
                                          .mips = mips,
                                          .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT});
    };
    // Per axis, rays travelling the positive way in the first half along the longest axis and the
    // negative way in the second (voxel_common.glsl).
    doubled_axis_ = int(std::max_element(&grid_.counts.x, &grid_.counts.x + 3) - &grid_.counts.x);
    glm::ivec3 extent = grid_.counts;
    extent[doubled_axis_] *= 2;
    const char* axes[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) seen_[a] = image(std::string("voxels seen along ") + axes[a], extent, levels_);
    opacity_ = image("voxels opacity", extent, levels_);
    images_new_ = true;
    allocated_counts_ = grid_.counts;
  }

  // Depth of every draw from the light, both sides of every face (lighting.deferred's shadow
  // shaders; alpha-tested materials are drawn opaque).
  void record_shadow(PassContext& ctx) {
    prepare(ctx);
    Image& map = ctx.image("tmp.shadow_map");
    const uint32_t size = map.desc().width;
    VkRenderingAttachmentInfo depth = cleared_attachment(map.view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(size, size, {}, &depth);
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBeginRendering(cmd, &rendering);
    if (light_present_ && rebuild_) {
      const Pipeline& pipeline = shadow_depth_pipeline(ctx, map.desc().format, false);
      set_viewport(cmd, size, size);
      const SceneView& scene = ctx.scene();
      for (uint32_t i = 0; i < scene.draws.size(); ++i) {
        const DescriptorWrite writes[] = {draw_block(0, draw_blocks_->handle(), i)};
        bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
        push_constants(cmd, pipeline, ShadowDrawPush{shadow_from_world_});
        draw_mesh(cmd, ctx.gpu_scene().mesh(scene.draws[i].mesh));
      }
    }
    vkCmdEndRendering(cmd);
  }

  // The steps in the node's own buffer and image, which the plan does not see, so it could not
  // order separate passes by them.
  void record_volume(PassContext& ctx) {
    prepare(ctx);
    if (rebuild_) {
      voxelize(ctx);
      inject(ctx, 0);
      build_chain(ctx);
      // The sky's and the local lights' light need the chain of the sun's to see what is open.
      const int32_t direct = (sky_ ? kInjectSky : 0) | (local_lights_.count > 0 ? kInjectLocalLights : 0);
      if (direct != 0) {
        if (sky_) sky_visibility(ctx);
        if (local_lights_.count > 0) local_lights(ctx);
        inject(ctx, direct);
        build_chain(ctx);
      }
      // Each further bounce: every voxel gathers the light the chain holds, and the injection adds
      // what its surface reflects of it to its direct light.
      for (int bounce = 1; bounce < bounces_; ++bounce) {
        gather_bounce(ctx);
        inject(ctx, direct | kInjectBounce);
        build_chain(ctx);
      }
    }
    trace_cones(ctx);
    if (ctx.has("out.volume")) write_volume(ctx);
  }

  // The optional volume output (linked or dumped), every mip from the chain's level of that
  // index (voxel_volume.comp), after trace_cones' barrier: the chain is only read since.
  void write_volume(PassContext& ctx) {
    Image& volume = ctx.image("out.volume");
    for (uint32_t level = 0; level < volume.desc().mips; ++level) {
      const DescriptorWrite writes[] = {
          uniform_buffer(0, constants_->handle()),
          sampled_image(1, seen_[0].view(), ctx.nearest_sampler(), VK_IMAGE_LAYOUT_GENERAL),
          sampled_image(2, seen_[1].view(), ctx.nearest_sampler(), VK_IMAGE_LAYOUT_GENERAL),
          sampled_image(3, seen_[2].view(), ctx.nearest_sampler(), VK_IMAGE_LAYOUT_GENERAL),
          sampled_image(4, opacity_.view(), ctx.nearest_sampler(), VK_IMAGE_LAYOUT_GENERAL),
          storage_image(5, volume.view({.base_mip = level, .mip_count = 1}))};
      const uint32_t w = std::max(volume.desc().width >> level, 1u), h = std::max(volume.desc().height >> level, 1u),
                     d = std::max(volume.desc().depth >> level, 1u);
      const int32_t push = int32_t(level);
      dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_volume.comp", writes, w, h * d,
                       std::as_bytes(std::span(&push, 1)));
    }
  }

  void voxelize(PassContext& ctx) {
    VkCommandBuffer cmd = ctx.cmd();
    // Last frame's injection read the sums; clear them for this frame's atomics.
    memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
                   {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    vkCmdFillBuffer(cmd, grid_sums_.handle(), 0, VK_WHOLE_SIZE, 0);
    memory_barrier(cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                   {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    voxelize_draws(ctx, "nodes/gi/voxel/shaders/voxelize.comp", grid_, *constants_, *draws_, grid_sums_);
  }

  // The sums into level 0 (the chain kept in the GENERAL layout); `second` adds the sky's light
  // (kInjectSky: each voxel's visibility in its sums, from sky_visibility()) and the local lights'
  // (kInjectLocalLights: their irradiance in the sums, from local_lights()) and the bounced light's
  // (kInjectBounce: its irradiance in the sums, from gather_bounce()).
  void inject(PassContext& ctx, int32_t second) {
    VkCommandBuffer cmd = ctx.cmd();
    if (images_new_) {
      for (const Image& seen : seen_) image_barrier(cmd, seen, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      image_barrier(cmd, opacity_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
    }
    images_new_ = false;
    compute_to_compute_barrier(cmd);  // the atomics; last frame's reads of the chain
    const DescriptorWrite writes[] = {uniform_buffer(0, constants_->handle()),
                                      storage_buffer(1, grid_sums_.handle()),
                                      sampled_image(2, ctx.image("tmp.shadow_map").view(), ctx.nearest_sampler()),
                                      storage_image(3, seen_[0].view({.base_mip = 0, .mip_count = 1})),
                                      storage_image(4, seen_[1].view({.base_mip = 0, .mip_count = 1})),
                                      storage_image(5, seen_[2].view({.base_mip = 0, .mip_count = 1})),
                                      storage_image(6, opacity_.view({.base_mip = 0, .mip_count = 1})),
                                      storage_buffer(7, sh_buffer(ctx))};
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_inject.comp", writes, uint32_t(grid_.counts.x),
                     uint32_t(grid_.counts.y * grid_.counts.z), std::as_bytes(std::span(&second, 1)));
  }

  // Per voxel, how much of the sky its surface sees through the chain (voxel_sky.comp), into its
  // sums.
  void sky_visibility(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the chain's last level
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_sky.comp", sums_and_chain(ctx), uint32_t(grid_.counts.x),
                     uint32_t(grid_.counts.y * grid_.counts.z));
  }

  // What the passes that light the voxels' sums through the chain bind (voxel_sky.comp,
  // voxel_local_lights.comp, voxel_bounce.comp): the constants, the sums, the chain as rays see it
  // and the opacity.
  std::vector<DescriptorWrite> sums_and_chain(PassContext& ctx) {
    return {uniform_buffer(0, constants_->handle()),
            storage_buffer(1, grid_sums_.handle()),
            sampled_image(4, seen_[0].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
            sampled_image(7, seen_[1].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
            sampled_image(8, seen_[2].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
            sampled_image(9, opacity_.view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL)};
  }

  // Per voxel, the local lights' irradiance on its surface with their visibility through the chain
  // (voxel_local_lights.comp), into its sums.
  void local_lights(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the chain's last level; the sky pass's sums
    std::vector<DescriptorWrite> writes = sums_and_chain(ctx);
    writes.push_back(uniform_buffer(10, lights_->handle()));
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_local_lights.comp", writes, uint32_t(grid_.counts.x),
                     uint32_t(grid_.counts.y * grid_.counts.z));
  }

  // Per voxel, the irradiance of the light the chain holds on its surface (voxel_bounce.comp),
  // into its sums.
  void gather_bounce(PassContext& ctx) {
    compute_to_compute_barrier(ctx.cmd());  // the chain's last level
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_bounce.comp", sums_and_chain(ctx), uint32_t(grid_.counts.x),
                     uint32_t(grid_.counts.y * grid_.counts.z));
  }

  // The environment's SH where the sky is linked, else a buffer of one zero coefficient.
  VkBuffer sh_buffer(PassContext& ctx) {
    return sky_ ? ctx.buffer("in.sh").handle() : no_sh_->handle();
  }

  void build_chain(PassContext& ctx) {
    for (uint32_t level = 1; level < levels_; ++level) {
      compute_to_compute_barrier(ctx.cmd());
      const glm::ivec3 counts = glm::max(grid_.counts >> int(level), glm::ivec3(1));
      std::vector<DescriptorWrite> writes = {uniform_buffer(0, constants_->handle())};
      for (uint32_t a = 0; a < 3; ++a)
        writes.push_back(storage_image(1 + a, seen_[a].view({.base_mip = level - 1, .mip_count = 1})));
      for (uint32_t a = 0; a < 3; ++a)
        writes.push_back(storage_image(4 + a, seen_[a].view({.base_mip = level, .mip_count = 1})));
      writes.push_back(storage_image(7, opacity_.view({.base_mip = level - 1, .mip_count = 1})));
      writes.push_back(storage_image(8, opacity_.view({.base_mip = level, .mip_count = 1})));
      const int32_t push = int32_t(level);
      dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_downsample.comp", writes, uint32_t(counts.x),
                       uint32_t(counts.y * counts.z), std::as_bytes(std::span(&push, 1)));
    }
  }

  void trace_cones(PassContext& ctx) {
    VkCommandBuffer cmd = ctx.cmd();
    compute_to_compute_barrier(cmd);
    // At the G-buffer's size: the cones start from positions reconstructed at its pixels.
    Image& depth = ctx.image("in.gbuffer", 0);
    const CameraConstants camera = camera_constants(ctx.scene().camera, depth.desc().width, depth.desc().height);
    Image& target = ctx.image(k_ == 1 ? "out.irradiance" : "tmp.lowres");
    Image& ao = ctx.image(k_ == 1 ? "out.ao" : "tmp.ao_lowres");
    Image& specular = ctx.image(k_ == 1 ? "out.specular" : "tmp.specular_lowres");
    // The specular cone only where its output is read (examples/gi-voxel.json does not link it):
    // else its image is neither written, kept nor copied back.
    const std::array<Image*, 3> all_targets{&target, &ao, &specular};
    const std::span<Image* const> targets(all_targets.data(), specular_read(ctx) ? 3 : 2);
    // A frame that changes neither the volume nor the camera (a jittered one changes the camera)
    // sees the same G-buffer: the cones' last results are copied back instead of traced.
    if (!rebuild_ && kept_camera_ &&
        std::memcmp(&*kept_camera_, &camera, sizeof(CameraConstants)) == 0) {
      for (size_t i = 0; i < targets.size(); ++i)
        copy_image(cmd, kept_[i], VK_IMAGE_LAYOUT_GENERAL, *targets[i], VK_IMAGE_LAYOUT_GENERAL);
      return;
    }
    camera_->write_value(camera);
    std::vector<DescriptorWrite> writes = {
        uniform_buffer(0, constants_->handle()),
        uniform_buffer(1, camera_->handle()),
        sampled_image(2, depth.view(), ctx.nearest_sampler()),
        sampled_image(3, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
        sampled_image(4, seen_[0].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
        storage_image(5, target.view()),
        storage_image(6, ao.view()),
        sampled_image(7, seen_[1].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
        sampled_image(8, seen_[2].view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
        sampled_image(9, opacity_.view(), ctx.linear_sampler(), VK_IMAGE_LAYOUT_GENERAL),
        sampled_image(10, ctx.image("in.gbuffer", 3).view(), ctx.nearest_sampler()),
        storage_image(11, specular.view()),
        storage_buffer(12, sh_buffer(ctx)),
        storage_buffer(13, grid_sums_.handle())};
    // kTraceSpecular and kGatherSky.
    const uint32_t constants[] = {specular_read(ctx) ? 1u : 0u, sky_ ? 1u : 0u};
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_cones.comp", writes, target.desc().width, target.desc().height,
                     std::as_bytes(std::span(&k_, 1)), kTileSize, constants);
    keep_cones(ctx, targets);
    kept_camera_ = camera;
  }

  // The cones' results into the node's own images (kept in the GENERAL layout), made at the
  // targets' sizes.
  void keep_cones(PassContext& ctx, std::span<Image* const> targets) {
    VkCommandBuffer cmd = ctx.cmd();
    for (size_t i = 0; i < targets.size(); ++i) {
      const ImageDesc& d = targets[i]->desc();
      if (kept_[i].desc().width != d.width || kept_[i].desc().height != d.height ||
          kept_[i].desc().format != d.format || !kept_camera_) {
        kept_[i] = Image::dedicated(ctx.gpu(), {.name = ctx.node().id + " kept " + d.name,
                                                .format = d.format,
                                                .width = d.width,
                                                .height = d.height});
      }
      copy_image(cmd, *targets[i], VK_IMAGE_LAYOUT_GENERAL, kept_[i], VK_IMAGE_LAYOUT_GENERAL);
    }
  }

  // At resolution_scale below 1, the cones' three smaller images to full resolution in one pass,
  // guided by depth and normals; at 1 the cones wrote the outputs themselves.
  void upsample(PassContext& ctx) {
    if (k_ == 1) return;
    Image& low = ctx.image("tmp.lowres");
    const DescriptorWrite writes[] = {sampled_image(0, low.view(), ctx.nearest_sampler()),
                                      sampled_image(1, ctx.image("in.gbuffer", 0).view(), ctx.nearest_sampler()),
                                      sampled_image(2, ctx.image("in.gbuffer", 1).view(), ctx.nearest_sampler()),
                                      storage_image(3, ctx.image("out.irradiance").view()),
                                      sampled_image(4, ctx.image("tmp.ao_lowres").view(), ctx.nearest_sampler()),
                                      storage_image(5, ctx.image("out.ao").view()),
                                      sampled_image(6, ctx.image("tmp.specular_lowres").view(), ctx.nearest_sampler()),
                                      storage_image(7, ctx.image("out.specular").view())};
    // kSpecular: the upsample writes the specular output only where the cones traced it.
    const uint32_t constants[] = {specular_read(ctx) ? 1u : 0u};
    dispatch_compute(ctx, "nodes/gi/voxel/shaders/voxel_upsample.comp", writes, low.desc().width, low.desc().height,
                     std::as_bytes(std::span(&k_, 1)), kTileSize, constants);
  }

  const int resolution_;
  const float ao_distance_;
  const int bounces_;
  const int32_t k_;  // the G-buffer's resolution over the cones' targets: 1 / resolution_scale
  std::optional<uint64_t> prepared_frame_;
  CellGrid grid_;
  glm::mat4 shadow_from_world_{1.0f};
  bool light_present_ = false;
  glm::ivec3 allocated_counts_{0};  // none yet
  uint32_t levels_ = 1;
  std::optional<HostBuffer> constants_, draws_, draw_blocks_, camera_;
  std::optional<HostBuffer> lights_;  // local_lights_.lights (voxel_local_lights.comp)
  std::optional<HostBuffer> no_sh_;  // bound in place of the SH where the sky is not injected
  Buffer grid_sums_;
  std::array<Image, 3> seen_;          // the chain as rays along x, y and z see it (voxel_common.glsl)
  Image opacity_;                      // each voxel's opacity along each axis (the same)
  int doubled_axis_ = 0;               // the axis along which those hold both directions
  bool images_new_ = false;            // not yet in the GENERAL layout
  bool rebuild_ = true;                // this frame voxelizes, injects and builds the chain
  std::array<Image, 3> kept_;                  // the cones' last irradiance, AO and specular where read
  std::optional<CameraConstants> kept_camera_;  // the camera they were traced from; none yet
  std::optional<bool> specular_read_;  // specular_read()'s, once found
  bool sky_ = false;                   // the environment's SH linked and the scene has an environment
  VoxelLocalLights local_lights_;      // this frame's (prepare())
  std::vector<std::byte> built_from_;  // what the chain was last built from (prepare())
};

}  // namespace

std::unique_ptr<NodeKernel> make_voxel_kernel(const PlanNode& node) {
  return std::make_unique<VoxelKernel>(node);
}

}  // namespace lg
