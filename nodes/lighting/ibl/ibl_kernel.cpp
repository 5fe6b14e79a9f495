#include "nodes/lighting/ibl/ibl_kernel.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "nodes/common/camera_constants.h"
#include "nodes/common/compute.h"
#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/env/common/sh_basis.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/host_buffer.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/vk_struct.h"
#include "runtime/scene/scene_view.h"

namespace lg {

namespace {

struct Push {  // nodes/lighting/ibl/shaders/ibl.comp
  float intensity;
};

Image fallback_image(Context& gpu, const char* name, ImageKind kind, VkFormat format) {
  return Image::dedicated(gpu, {.name = std::string("lighting.ibl fallback ") + name,
                                .kind = kind,
                                .format = format,
                                .layers = kind == ImageKind::cube ? 6u : 1u});
}

class IblKernel final : public NodeKernel {
 public:
  explicit IblKernel(const PlanNode& node)
      : settings_{param_string(node, "diffuse_source") == "sh", float(param_number(node, "intensity")),
                  param_bool(node, "specular_occlusion"), param_bool(node, "multi_bounce")} {}

  void record(PassContext& ctx) override {
    if (!camera_) camera_.emplace(ctx.gpu(), ctx.node().id + " camera", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!fallbacks_) fallbacks_.emplace(ctx.gpu());
    Image& color = ctx.image("out.color");
    camera_->write_value(camera_constants(ctx.scene().camera, color.desc().width, color.desc().height));
    IblInputs in;
    in.camera = camera_->handle();
    in.depth = &ctx.image("in.gbuffer", 0);
    in.normal = &ctx.image("in.gbuffer", 1);
    in.albedo = &ctx.image("in.gbuffer", 2);
    in.material = &ctx.image("in.gbuffer", 3);
    in.direct = ctx.has("in.direct") ? &ctx.image("in.direct") : nullptr;
    in.sh = ctx.has("in.sh") ? &ctx.buffer("in.sh") : nullptr;
    in.irradiance = ctx.has("in.irradiance") ? &ctx.image("in.irradiance") : nullptr;
    in.specular = &ctx.image("in.specular");
    in.brdf_lut = &ctx.image("in.brdf_lut");
    in.ao = ctx.has("in.ao") ? &ctx.image("in.ao") : nullptr;
    in.bent_normals = ctx.has("in.bent_normals") ? &ctx.image("in.bent_normals") : nullptr;
    in.irradiance_volume = ctx.has("in.irradiance_volume") ? &ctx.image("in.irradiance_volume") : nullptr;
    in.ssr = ctx.has("in.ssr") ? &ctx.image("in.ssr") : nullptr;
    in.reflection_probes = ctx.has("in.reflection_probes") ? &ctx.image("in.reflection_probes") : nullptr;
    in.color = &color;
    // Without an environment the node runs only for a linked volume (its bypass): the graph's
    // environment nodes stand in for a sky the scene does not have, so their light counts nothing.
    IblSettings settings = settings_;
    if (!ctx.scene().has_environment) settings.intensity = 0.0f;
    record_ibl(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, settings, in, *fallbacks_, ctx.linear_sampler(),
               ctx.nearest_sampler());
  }

 private:
  IblSettings settings_;
  std::optional<HostBuffer> camera_;
  std::optional<IblFallbacks> fallbacks_;
};

}  // namespace

IblFallbacks::IblFallbacks(Context& gpu)
    : direct(fallback_image(gpu, "direct", ImageKind::image2d, VK_FORMAT_R16G16B16A16_SFLOAT)),
      ao(fallback_image(gpu, "ao", ImageKind::image2d, VK_FORMAT_R8_UNORM)),
      bent_normals(fallback_image(gpu, "bent normals", ImageKind::image2d, VK_FORMAT_R8G8B8A8_SNORM)),
      irradiance(fallback_image(gpu, "irradiance", ImageKind::cube, VK_FORMAT_R16G16B16A16_SFLOAT)),
      sh(Buffer::dedicated(gpu, {.name = "lighting.ibl fallback sh", .size = 16})) {}

void IblFallbacks::prepare(VkCommandBuffer cmd) {
  if (cleared_) return;
  cleared_ = true;
  const VkClearColorValue zero{};
  for (Image* image : {&direct, &ao, &bent_normals, &irradiance}) {
    image_barrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE},
                  {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    const VkImageSubresourceRange range = image->whole_range();
    vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    image_barrier(cmd, *image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                  {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                  {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  }
  vkCmdFillBuffer(cmd, sh.handle(), 0, VK_WHOLE_SIZE, 0);
  auto b = vk_struct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
  b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, b.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  b.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, b.dstAccessMask = VK_ACCESS_2_UNIFORM_READ_BIT;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = sh.handle();
  b.size = VK_WHOLE_SIZE;
  auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void record_ibl(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                const IblSettings& settings, const IblInputs& in, IblFallbacks& fallbacks, VkSampler linear,
                VkSampler nearest) {
  if (!in.depth || !in.normal || !in.albedo || !in.material || !in.specular || !in.brdf_lut || !in.color)
    throw std::invalid_argument(name + ": the G-buffer, specular, brdf_lut and color are required");
  fallbacks.prepare(cmd);
  uint32_t flags = settings.diffuse_from_sh ? 1u : 0u;
  if (in.direct) flags |= 2u;
  if (in.ao) flags |= 4u;
  if (in.bent_normals) flags |= 8u;
  if (settings.specular_occlusion) flags |= 16u;
  if (settings.multi_bounce) flags |= 32u;
  if (in.irradiance_volume) flags |= 64u;
  if (in.ssr) flags |= 128u;
  if (in.reflection_probes) flags |= 256u;
  const Buffer& sh = in.sh ? *in.sh : fallbacks.sh;
  const DescriptorWrite writes[] = {
      uniform_buffer(0, in.camera),
      sampled_image(1, in.depth->view(), nearest),
      sampled_image(2, in.normal->view(), nearest),
      sampled_image(3, in.albedo->view(), nearest),
      sampled_image(4, in.material->view(), nearest),
      sampled_image(5, (in.direct ? in.direct : &fallbacks.direct)->view(), nearest),
      uniform_buffer(6, sh.handle()),  // ibl_environment.glsl: a uniform block in this pass
      sampled_image(7, (in.irradiance ? in.irradiance : &fallbacks.irradiance)->view(), linear),
      sampled_image(8, in.specular->view(), linear),
      sampled_image(9, in.brdf_lut->view(), linear),
      sampled_image(10, (in.ao ? in.ao : &fallbacks.ao)->view(), nearest),
      sampled_image(11, (in.bent_normals ? in.bent_normals : &fallbacks.bent_normals)->view(), nearest),
      storage_image(12, in.color->view()),
      sampled_image(13, (in.irradiance_volume ? in.irradiance_volume : &fallbacks.direct)->view(), nearest),
      sampled_image(14, (in.ssr ? in.ssr : &fallbacks.direct)->view(), nearest),
      sampled_image(15, (in.reflection_probes ? in.reflection_probes : &fallbacks.direct)->view(), nearest),
  };
  std::vector<DescriptorBinding> bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}};
  for (uint32_t b = 1; b <= 11; ++b)
    bindings.push_back({b, b == 6 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  bindings.push_back({12, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  for (uint32_t b = 13; b <= 15; ++b) bindings.push_back({b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  // The shader's specialization constants: the flags, and the SH coefficients the buffer holds.
  const uint32_t coefficients =
      uint32_t(std::min<uint64_t>(sh.size() / (4 * sizeof(float)), uint64_t(sh_count(kMaxShOrder))));
  const Pipeline& pipeline = pipelines.compute({name, node_shader("nodes/lighting/ibl/shaders/ibl.comp"),
                                                std::move(bindings), sizeof(Push), {flags, coefficients}});
  bind_pipeline(gpu, cmd, pipeline, writes);
  push_constants(cmd, pipeline, Push{settings.intensity});
  dispatch_texels(cmd, in.color->desc().width, in.color->desc().height);
}

std::unique_ptr<NodeKernel> make_ibl_kernel(const PlanNode& node) {
  return std::make_unique<IblKernel>(node);
}

}  // namespace lg
