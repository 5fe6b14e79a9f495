#include "nodes/env/load/env_load_kernel.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <utility>

#include "nodes/common/node_params.h"
#include "nodes/common/node_shaders.h"
#include "nodes/env/common/equirect.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/pipeline.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

constexpr uint32_t kGroup = 8;

void barrier(VkCommandBuffer cmd, const Image* image, VkImageLayout from, VkImageLayout to,
             VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
             VkAccessFlags2 dst_access) {
  auto b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  b.srcStageMask = src_stage, b.srcAccessMask = src_access, b.dstStageMask = dst_stage, b.dstAccessMask = dst_access;
  b.oldLayout = from, b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image->handle();
  b.subresourceRange = image->whole_range();
  auto dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

class EnvLoadKernel final : public NodeKernel {
 public:
  // The file is opened here, so that a missing or broken file fails before any frame.
  explicit EnvLoadKernel(const PlanNode& node)
      : id_(node.id),
        path_(param_string(node, "path")),
        intensity_(param_number(node, "intensity")),
        file_(std::in_place, path_) {}

  void record(PassContext& ctx) override {
    if (!source_) {
      if (!file_) file_.emplace(path_);  // recorded again after frame_finished(): read the file again
      uint64_t non_finite = 0;
      EquirectSource source = read_equirect(ctx.gpu(), *file_, intensity_, non_finite);
      if (non_finite)
        std::cerr << "env.load '" << id_ << "': " << non_finite << " non-finite texels of " << path_
                  << " replaced by 0\n";
      source_.emplace(std::move(source));
      file_.reset();
    }
    record_env_load(ctx.gpu(), ctx.pipelines(), ctx.cmd(), ctx.pass().name, *source_, ctx.nearest_sampler(),
                    ctx.image("out.cube"));
  }

  // The source holds two float copies of the file (the staging buffer and the equirect image,
  // 1 GiB for an 8192x4096 one) that only this pass reads, and its result is cached. The file
  // is still open when the pass never recorded (its result adopted from an earlier executor).
  void frame_finished() override {
    source_.reset();
    file_.reset();
  }

 private:
  std::string id_, path_;
  double intensity_;
  std::optional<ImageReader> file_;       // until its pixels are in the staging buffer, or the frame ends
  std::optional<EquirectSource> source_;  // from a record to the end of its frame
};

}  // namespace

uint32_t equirect_supersample(uint32_t equirect_width, uint32_t face_size) {
  // A face spans a quarter of the width; a cube texel about width / (4 face) equirect texels.
  return std::clamp((equirect_width + 4 * face_size - 1) / (4 * face_size), 1u, 8u);
}

EquirectSource::EquirectSource(Context& gpu, uint32_t width, uint32_t height)
    : image(Image::dedicated(
          gpu,
          {.name = "env.load equirect", .format = VK_FORMAT_R32G32B32A32_SFLOAT, .width = width, .height = height})),
      staging_(Buffer::dedicated(
          gpu, {.name = "env.load staging", .size = uint64_t(width) * height * 4 * sizeof(float)}, MemoryUse::upload)) {
}

std::span<float> EquirectSource::texels() {
  return {reinterpret_cast<float*>(staging_.mapped()), size_t(staging_.size() / sizeof(float))};
}

EquirectSource read_equirect(Context& gpu, ImageReader& file, double intensity, uint64_t& non_finite) {
  EquirectSource source(gpu, file.width(), file.height());
  file.read_rgba(source.texels());
  non_finite = sanitize_equirect(source.texels(), intensity);
  return source;
}

void EquirectSource::upload(VkCommandBuffer cmd) {
  barrier(cmd, &image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
          VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {image.desc().width, image.desc().height, 1};
  vkCmdCopyBufferToImage(cmd, staging_.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  barrier(cmd, &image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
          VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void record_env_load(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                     EquirectSource& source, VkSampler nearest, Image& cube) {
  source.upload(cmd);
  auto mip_view = [&](uint32_t mip) {
    return cube.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1});
  };
  auto dispatch = [&](uint32_t size) {
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  };
  const uint32_t face = cube.desc().width;
  const Pipeline& resample =
      pipelines.compute({name + " resample",
                         node_shader("nodes/env/load/shaders/equirect_to_cube.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                         sizeof(int32_t)});
  const DescriptorWrite resample_writes[] = {sampled_image(0, source.image.view(), nearest),
                                             storage_image(1, mip_view(0))};
  bind_pipeline(gpu, cmd, resample, resample_writes);
  push_constants(cmd, resample, int32_t(equirect_supersample(source.image.desc().width, face)));
  dispatch(face);

  const Pipeline& downsample =
      pipelines.compute({name + " mips",
                         node_shader("nodes/env/load/shaders/cube_downsample.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}});
  for (uint32_t mip = 1; mip < cube.desc().mips; ++mip) {
    // The finer mip's writes before this dispatch's reads (the image stays in GENERAL).
    barrier(cmd, &cube, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    const DescriptorWrite writes[] = {sampled_image(0, mip_view(mip - 1), nearest, VK_IMAGE_LAYOUT_GENERAL),
                                      storage_image(1, mip_view(mip))};
    bind_pipeline(gpu, cmd, downsample, writes);
    dispatch(std::max(1u, face >> mip));
  }
}

std::unique_ptr<NodeKernel> make_env_load_kernel(const PlanNode& node) {
  return std::make_unique<EnvLoadKernel>(node);
}

}  // namespace lg
