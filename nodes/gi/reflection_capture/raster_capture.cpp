#include "nodes/gi/reflection_capture/raster_capture.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "nodes/common/node_shaders.h"
#include "nodes/gi/irradiance_volume/probe_atlas.h"
#include "nodes/gi/irradiance_volume/probe_volume_source.h"
#include "nodes/gi/reflection_capture/cube_face_camera.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "nodes/scene/gbuffer/material_textures.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"

namespace lg {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// Each view's constants and settings at a multiple of these: of the largest
// minUniformBufferOffsetAlignment Vulkan allows, so any device takes the offsets.
constexpr size_t kConstantsStride = (sizeof(LightConstants) + 255) / 256 * 256;
constexpr size_t kSettingsStride = (sizeof(ForwardSettings) + 255) / 256 * 256;

constexpr SyncScope kAttachmentWrite{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
constexpr SyncScope kDepthAccess{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
// The cubes are read by the prefilter (compute) and by readbacks (transfer).
constexpr SyncScope kCubeReaders{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT};

// capture_surface.glsl's probe volume: its volumes' block and three atlas images.
constexpr uint32_t kVolumeBinding = 23, kRecordBinding = 24, kIrradianceBinding = 25, kDistanceBinding = 26;

void add_volume_bindings(GraphicsPipelineDesc& desc) {
  desc.bindings.push_back({kVolumeBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
  for (uint32_t b : {kRecordBinding, kIrradianceBinding, kDistanceBinding})
    desc.bindings.push_back({b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
}

void add_volume_writes(std::vector<DescriptorWrite>& writes, const CaptureResources& r) {
  // The atlas maps are filtered; the placeholders (a depth image) cannot be, and are not read.
  const VkSampler maps = r.volume.linked ? r.forward.linear : r.forward.nearest;
  writes.push_back(uniform_buffer(kVolumeBinding, r.volume.volumes));
  writes.push_back(sampled_image(kRecordBinding, r.volume.records, r.forward.nearest));
  writes.push_back(sampled_image(kIrradianceBinding, r.volume.irradiance, maps));
  writes.push_back(sampled_image(kDistanceBinding, r.volume.distance, maps));
}

// The gi.irradiance_volume kernel behind the linked `probe_volume`, or null where it is unlinked.
ProbeVolumeSource* linked_volume(PassContext& ctx) {
  if (!ctx.has("in.probe_volume")) return nullptr;
  auto* source = dynamic_cast<ProbeVolumeSource*>(ctx.producer("in.probe_volume"));
  if (!source)
    throw std::runtime_error(ctx.node().type + " '" + ctx.node().id +
                             "': the input 'probe_volume' must come from a gi.irradiance_volume's 'probes'");
  return source;
}

}  // namespace

RasterCapture::RasterCapture(Context& gpu, const std::string& name)
    : name_(name + " capture"),
      lights_(gpu, name_),
      draws_(gpu, name_ + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      settings_(gpu, name_ + " settings", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      cameras_(gpu, name_ + " face constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) {}

uint64_t CaptureInputs::volume_version(PassContext& ctx) {
  ProbeVolumeSource* source = linked_volume(ctx);
  return source ? source->probe_volume().version : 0;
}

CaptureResources CaptureInputs::bind(PassContext& ctx, float intensity, ForwardSettings& settings) {
  const bool environment = ctx.scene().has_environment;
  const bool sh = ctx.has("in.sh");
  if (environment && (!ctx.has("in.specular") || !ctx.has("in.brdf_lut") || (!sh && !ctx.has("in.irradiance"))))
    throw std::runtime_error(ctx.node().type + " '" + ctx.node().id +
                             "': under an environment light the inputs 'specular', 'brdf_lut' and 'sh' or "
                             "'irradiance' must be linked");
  settings.flags = (environment ? 1u : 0u) | (sh ? 2u : 0u);
  settings.intensity = intensity;
  if (!sh_placeholder_) {
    sh_placeholder_.emplace(ctx.gpu(), ctx.node().id + " no SH", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    sh_placeholder_->write(std::vector<float>(4, 0.0f));
    cube_placeholder_.emplace(Image::dedicated(ctx.gpu(), {.name = ctx.node().id + " no cube",
                                                           .kind = ImageKind::cube,
                                                           .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                           .layers = 6,
                                                           .usage = VK_IMAGE_USAGE_SAMPLED_BIT}));
    image_barrier(ctx.cmd(), *cube_placeholder_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                  {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
                  {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE});
  }
  const VkImageView no_cube = cube_placeholder_->view();
  const VkImageView placeholder_2d = ctx.image("in.gbuffer", 0).view();
  CaptureResources out{.forward = {.sh = sh ? ctx.buffer("in.sh").handle() : sh_placeholder_->handle(),
                                   .irradiance = ctx.has("in.irradiance") ? ctx.image("in.irradiance").view() : no_cube,
                                   .specular = environment ? ctx.image("in.specular").view() : no_cube,
                                   .brdf_lut = ctx.has("in.brdf_lut") ? ctx.image("in.brdf_lut").view()
                                                                      : ctx.image("in.gbuffer", 1).view(),
                                   .placeholder_2d = placeholder_2d,
                                   .linear = ctx.linear_sampler(),
                                   .nearest = ctx.nearest_sampler()},
                       .volume = {}};
  if (!volumes_placeholder_) {
    volumes_placeholder_.emplace(ctx.gpu(), ctx.node().id + " no probe volumes", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    volumes_placeholder_->write(std::vector<GpuProbeVolume>(kMaxProbeVolumes));
  }
  out.volume = {.volumes = volumes_placeholder_->handle(),
                .records = placeholder_2d,
                .irradiance = placeholder_2d,
                .distance = placeholder_2d};
  if (ProbeVolumeSource* source = linked_volume(ctx)) {
    // The volume's diffuse light takes what the specular leaves, by the DFG table, as in the frame.
    if (!ctx.has("in.brdf_lut"))
      throw std::runtime_error(ctx.node().type + " '" + ctx.node().id +
                               "': with 'probe_volume' linked the input 'brdf_lut' must be linked too");
    const ProbeVolumeBinding b = source->probe_volume();
    if (!b.atlas)
      throw std::logic_error(ctx.node().type + " '" + ctx.node().id + "': the linked volume has no probes yet");
    out.volume = {.linked = true,
                  .representation = b.representation,
                  .visibility = b.visibility,
                  .volumes = ctx.buffer("in.probe_volume").handle(),
                  .records = b.atlas->records().view(),
                  .irradiance = b.atlas->irradiance().view(),
                  .distance = b.atlas->distance().view()};
    settings.volume_count = b.volume_count;
    settings.volume_normal_bias = b.normal_bias;
    settings.volume_view_bias = b.view_bias;
  }
  return out;
}

void RasterCapture::record(PassContext& ctx, std::span<const CubeFace> faces, std::span<Image> cubes,
                           const CaptureResources& resources, const ForwardSettings& settings,
                           std::span<const VkImageView> specular) {
  if (faces.empty()) return;
  const SceneView& scene = ctx.scene();
  const uint32_t size = cubes[0].desc().width;
  std::vector<CaptureView> views;
  for (const CubeFace& f : faces) {
    const glm::vec3 position(scene.reflection_probes.at(f.probe).world[3]);
    views.push_back(
        {cube_face_camera(position, f.face, size, scene.camera.near_plane),
         cubes[f.probe].view(
             {.type = VK_IMAGE_VIEW_TYPE_2D, .mip_count = 1, .base_layer = uint32_t(f.face), .layer_count = 1}),
         size, size, specular.empty() ? VK_NULL_HANDLE : specular[f.probe]});
  }
  VkCommandBuffer cmd = ctx.cmd();
  std::vector<bool> touched(cubes.size(), false);
  for (const CubeFace& f : faces) touched.at(f.probe) = true;
  for (size_t p = 0; p < cubes.size(); ++p)
    if (touched[p])
      image_barrier(cmd, cubes[p], VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                    {kCubeReaders.stages, VK_ACCESS_2_NONE}, kAttachmentWrite);
  record_views(ctx, views, cubes[0].desc().format, resources, settings, true);
  for (size_t p = 0; p < cubes.size(); ++p)
    if (touched[p])
      image_barrier(cmd, cubes[p], VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                    kAttachmentWrite, kCubeReaders);
}

void RasterCapture::record_views(PassContext& ctx, std::span<const CaptureView> views, VkFormat format,
                                 const CaptureResources& resources, const ForwardSettings& settings, bool probes_only) {
  if (views.empty()) return;
  const SceneView& scene = ctx.scene();
  uint32_t width = 0, height = 0;
  for (const CaptureView& v : views) width = std::max(width, v.width), height = std::max(height, v.height);
  prepare_depth(ctx, width, height);
  // One constants block per view (the lights' counts and a camera of its own), and one
  // settings block (its clip plane).
  LightConstants constants{};
  lights_.write_lights(scene, -1, no_local_shadows(scene), constants);
  std::vector<std::byte> blocks(views.size() * kConstantsStride), settings_blocks(views.size() * kSettingsStride);
  for (size_t k = 0; k < views.size(); ++k) {
    constants.camera = views[k].camera;
    std::memcpy(blocks.data() + k * kConstantsStride, &constants, sizeof constants);
    ForwardSettings view_settings = settings;
    view_settings.clip_plane = views[k].clip_plane;
    std::memcpy(settings_blocks.data() + k * kSettingsStride, &view_settings, sizeof view_settings);
  }
  cameras_.write(std::span<const std::byte>(blocks));
  settings_.write(std::span<const std::byte>(settings_blocks));
  draws_.write(draw_constants(scene));

  VkCommandBuffer cmd = ctx.cmd();
  // The node's pass is a compute pass: the plan made its inputs visible to compute shaders,
  // this makes them visible to the vertex and fragment stages too (a chained dependency).
  memory_barrier(
      cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE},
      {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});
  GpuScene& gpu_scene = ctx.gpu_scene();
  const Pipeline& sky = sky_pipeline(ctx, format);
  for (size_t k = 0; k < views.size(); ++k) {
    const CaptureView& view = views[k];
    memory_barrier(cmd, kDepthAccess, kDepthAccess);  // the depth target is reused, view after view
    ForwardResources view_resources = resources.forward;
    if (view.specular != VK_NULL_HANDLE) view_resources.specular = view.specular;
    std::vector<DescriptorWrite> writes = forward_writes(lights_, draws_.handle(), settings_.handle(), view_resources);
    writes[0] = uniform_buffer(0, cameras_.handle(), k * kConstantsStride, sizeof(LightConstants));
    *std::find_if(writes.begin(), writes.end(), [](const DescriptorWrite& w) { return w.binding == 20; }) =
        uniform_buffer(20, settings_.handle(), k * kSettingsStride, sizeof(ForwardSettings));
    add_volume_writes(writes, resources);
    const size_t shared = writes.size();

    // The sky covers every texel first, so the colour's old contents are not loaded.
    VkRenderingAttachmentInfo color = cleared_attachment(view.target);
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    VkRenderingAttachmentInfo depth = cleared_attachment(depth_->view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(view.width, view.height, {&color, 1}, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    set_viewport(cmd, view.width, view.height);
    bind_pipeline(ctx.gpu(), cmd, sky, writes);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    for (uint32_t i = 0; i < scene.draws.size(); ++i) {
      const DrawItem& d = scene.draws[i];
      const PbrMaterial& m = scene.material_of(d);
      if (m.alpha_mode == AlphaMode::blend || (probes_only && !d.captured_by_probes)) continue;
      writes.resize(shared);
      add_material_textures(gpu_scene, m, writes);
      const Pipeline& pipeline =
          mesh_pipeline(ctx, format, m.alpha_mode == AlphaMode::mask, m.double_sided, resources.volume);
      bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, gpu_scene.mesh(d.mesh));
    }
    vkCmdEndRendering(cmd);
  }
}

void RasterCapture::prepare_depth(PassContext& ctx, uint32_t width, uint32_t height) {
  if (depth_ && depth_->desc().width >= width && depth_->desc().height >= height) return;
  depth_.emplace(Image::dedicated(
      ctx.gpu(), {.name = name_ + " depth", .format = kDepthFormat, .width = width, .height = height}));
  image_barrier(ctx.cmd(), *depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE}, kDepthAccess);
}

// The full-screen triangle of scene.forward_transparent's copy with capture_sky.frag, bound with
// the meshes' bindings; no depth test (it is drawn first, at no depth).
const Pipeline& RasterCapture::sky_pipeline(PassContext& ctx, VkFormat color) {
  GraphicsPipelineDesc desc =
      forward_pipeline_desc(ctx.pass().name + " capture sky",
                            node_shader("nodes/gi/reflection_capture/shaders/capture_sky.frag"), color, true);
  desc.vertex_shader = node_shader("nodes/scene/forward_transparent/shaders/copy.vert");
  desc.vertex_bindings.clear();
  desc.vertex_attributes.clear();
  desc.depth_format = kDepthFormat;
  add_volume_bindings(desc);
  return ctx.pipelines().graphics(desc);
}

// The views are mirror images of a right-handed view (cube faces, mirrored cameras): front faces
// wind clockwise. Depth tested and written, reversed Z.
const Pipeline& RasterCapture::mesh_pipeline(PassContext& ctx, VkFormat color, bool masked, bool double_sided,
                                             const CaptureVolume& volume) {
  GraphicsPipelineDesc desc =
      forward_pipeline_desc(ctx.pass().name + " capture",
                            node_shader(masked ? "nodes/gi/reflection_capture/shaders/capture_masked.frag"
                                               : "nodes/gi/reflection_capture/shaders/capture.frag"),
                            color, double_sided);
  desc.front_face = VK_FRONT_FACE_CLOCKWISE;
  desc.depth_format = kDepthFormat;
  desc.depth_test = desc.depth_write = true;
  add_volume_bindings(desc);
  // capture_surface.glsl: the lights' two constants at their defaults (true), then whether the
  // volume is read, its representation and its visibility test.
  desc.fragment_constants = {1u, 1u, volume.linked ? 1u : 0u, volume.representation, volume.visibility ? 1u : 0u};
  return ctx.pipelines().graphics(desc);
}

}  // namespace lg
