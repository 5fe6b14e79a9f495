#include "nodes/gi/reflection_capture/raster_cube_capture.h"

#include <cstring>
#include <vector>

#include "nodes/common/node_shaders.h"
#include "nodes/gi/reflection_capture/cube_face_camera.h"
#include "nodes/scene/gbuffer/draw_constants.h"
#include "nodes/scene/gbuffer/material_textures.h"
#include "runtime/exec/gpu_scene.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"

namespace lg {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
// Each face's constants at a multiple of this: the largest minUniformBufferOffsetAlignment
// Vulkan allows, so any device takes the offsets.
constexpr size_t kConstantsStride = (sizeof(LightConstants) + 255) / 256 * 256;

constexpr SyncScope kAttachmentWrite{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
constexpr SyncScope kDepthAccess{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
// The cubes are read by the prefilter (compute) and by readbacks (transfer).
constexpr SyncScope kCubeReaders{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT};

}  // namespace

RasterCubeCapture::RasterCubeCapture(Context& gpu, const std::string& name)
    : name_(name + " capture"),
      lights_(gpu, name_),
      draws_(gpu, name_ + " draws", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      settings_(gpu, name_ + " settings", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      cameras_(gpu, name_ + " face constants", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT) {}

void RasterCubeCapture::record(PassContext& ctx, std::span<const CubeFace> faces, std::span<Image> cubes,
                               const ForwardResources& resources, const ForwardSettings& settings,
                               std::span<const VkImageView> specular) {
  if (faces.empty()) return;
  const SceneView& scene = ctx.scene();
  const uint32_t size = cubes[0].desc().width;
  const VkFormat format = cubes[0].desc().format;
  prepare_depth(ctx, size);
  // One constants block per face: the lights' counts and a camera of its own.
  LightConstants constants{};
  lights_.write_lights(scene, -1, no_local_shadows(scene), constants);
  std::vector<std::byte> blocks(faces.size() * kConstantsStride);
  for (size_t k = 0; k < faces.size(); ++k) {
    const glm::vec3 position(scene.reflection_probes.at(faces[k].probe).world[3]);
    constants.camera = cube_face_camera(position, faces[k].face, size, scene.camera.near_plane);
    std::memcpy(blocks.data() + k * kConstantsStride, &constants, sizeof constants);
  }
  cameras_.write(std::span<const std::byte>(blocks));
  draws_.write(draw_constants(scene));
  settings_.write_value(settings);

  VkCommandBuffer cmd = ctx.cmd();
  // The node's pass is a compute pass: the plan made its inputs visible to compute shaders,
  // this makes them visible to the vertex and fragment stages too (a chained dependency).
  memory_barrier(
      cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE},
      {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});
  std::vector<bool> touched(cubes.size(), false);
  for (const CubeFace& f : faces) touched.at(f.probe) = true;
  for (size_t p = 0; p < cubes.size(); ++p)
    if (touched[p])
      image_barrier(cmd, cubes[p], VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                    {kCubeReaders.stages, VK_ACCESS_2_NONE}, kAttachmentWrite);

  GpuScene& gpu_scene = ctx.gpu_scene();
  const Pipeline& sky = sky_pipeline(ctx, format);
  for (size_t k = 0; k < faces.size(); ++k) {
    const CubeFace& f = faces[k];
    memory_barrier(cmd, kDepthAccess, kDepthAccess);  // the depth target is reused, face after face
    ForwardResources probe_resources = resources;
    if (!specular.empty()) probe_resources.specular = specular[f.probe];
    std::vector<DescriptorWrite> writes = forward_writes(lights_, draws_.handle(), settings_.handle(), probe_resources);
    writes[0] = uniform_buffer(0, cameras_.handle(), k * kConstantsStride, sizeof(LightConstants));
    const size_t shared = writes.size();

    // The sky covers every texel first, so the colour's old contents are not loaded.
    VkRenderingAttachmentInfo color = cleared_attachment(cubes[f.probe].view(
        {.type = VK_IMAGE_VIEW_TYPE_2D, .mip_count = 1, .base_layer = uint32_t(f.face), .layer_count = 1}));
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    VkRenderingAttachmentInfo depth = cleared_attachment(depth_->view(), {.depthStencil = {0.0f, 0}});
    const VkRenderingInfo rendering = rendering_info(size, size, {&color, 1}, &depth);
    vkCmdBeginRendering(cmd, &rendering);
    set_viewport(cmd, size, size);
    bind_pipeline(ctx.gpu(), cmd, sky, writes);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    for (uint32_t i = 0; i < scene.draws.size(); ++i) {
      const DrawItem& d = scene.draws[i];
      const PbrMaterial& m = scene.material_of(d);
      if (m.alpha_mode == AlphaMode::blend || !d.captured_by_probes) continue;
      writes.resize(shared);
      add_material_textures(gpu_scene, m, writes);
      const Pipeline& pipeline = mesh_pipeline(ctx, format, m.alpha_mode == AlphaMode::mask, m.double_sided);
      bind_pipeline(ctx.gpu(), cmd, pipeline, writes);
      push_constants(cmd, pipeline, i);
      draw_mesh(cmd, gpu_scene.mesh(d.mesh));
    }
    vkCmdEndRendering(cmd);
  }
  for (size_t p = 0; p < cubes.size(); ++p)
    if (touched[p])
      image_barrier(cmd, cubes[p], VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                    kAttachmentWrite, kCubeReaders);
}

void RasterCubeCapture::prepare_depth(PassContext& ctx, uint32_t size) {
  if (depth_ && depth_->desc().width == size) return;
  depth_.emplace(
      Image::dedicated(ctx.gpu(), {.name = name_ + " depth", .format = kDepthFormat, .width = size, .height = size}));
  image_barrier(ctx.cmd(), *depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL,
                {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE}, kDepthAccess);
}

// The full-screen triangle of scene.forward_transparent's copy with capture_sky.frag, bound with
// the meshes' bindings; no depth test (it is drawn first, at no depth).
const Pipeline& RasterCubeCapture::sky_pipeline(PassContext& ctx, VkFormat color) {
  GraphicsPipelineDesc desc =
      forward_pipeline_desc(ctx.pass().name + " capture sky",
                            node_shader("nodes/gi/reflection_capture/shaders/capture_sky.frag"), color, true);
  desc.vertex_shader = node_shader("nodes/scene/forward_transparent/shaders/copy.vert");
  desc.vertex_bindings.clear();
  desc.vertex_attributes.clear();
  desc.depth_format = kDepthFormat;
  return ctx.pipelines().graphics(desc);
}

// The faces are mirror images of a right-handed view (cube_face_camera.h): front faces wind
// clockwise. Depth tested and written, reversed Z.
const Pipeline& RasterCubeCapture::mesh_pipeline(PassContext& ctx, VkFormat color, bool masked, bool double_sided) {
  GraphicsPipelineDesc desc =
      forward_pipeline_desc(ctx.pass().name + " capture",
                            node_shader(masked ? "nodes/gi/reflection_capture/shaders/capture_masked.frag"
                                               : "nodes/gi/reflection_capture/shaders/capture.frag"),
                            color, double_sided);
  desc.front_face = VK_FRONT_FACE_CLOCKWISE;
  desc.depth_format = kDepthFormat;
  desc.depth_test = desc.depth_write = true;
  return ctx.pipelines().graphics(desc);
}

}  // namespace lg
