#include "nodes/gi/reflection_capture/probe_cubes.h"

#include <algorithm>
#include <bit>

#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "runtime/gpu/direct_barriers.h"

namespace lg {
namespace {

constexpr SyncScope kTransferWrite{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
constexpr SyncScope kTransferRead{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
constexpr SyncScope kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
constexpr SyncScope kNothing{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
// What an earlier prefilter of the same probe did to its chain and result: wrote them, then copied.
constexpr SyncScope kEarlierPrefilter{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The array is read by the lookup (compute) and a second bounce's capture (fragment).
constexpr SyncScope kArrayReaders{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};

Image cube_image(Context& gpu, const std::string& name, uint32_t size, uint32_t mips, uint32_t cubes = 1) {
  return Image::dedicated(gpu, {.name = name,
                                .kind = ImageKind::cube,
                                .format = ProbeCubes::kFormat,
                                .width = size,
                                .height = size,
                                .mips = mips,
                                .layers = 6 * cubes});
}

}  // namespace

bool ProbeCubes::prepare(PassContext& ctx, size_t count, uint32_t size, uint32_t mips) {
  if (array_ && captured_.size() == count && size_ == size && mips_ == mips) return false;
  Context& gpu = ctx.gpu();
  VkCommandBuffer cmd = ctx.cmd();
  const std::string& name = ctx.node().id;
  size_ = size, mips_ = mips;
  captured_.clear();
  chains_.clear();
  for (size_t i = 0; i < count; ++i) {
    const std::string probe = name + " probe " + std::to_string(i);
    captured_.push_back(cube_image(gpu, probe + " captured", size, 1));
    chains_.push_back({cube_image(gpu, probe + " chain", size, uint32_t(std::bit_width(size))),
                       cube_image(gpu, probe + " prefiltered", size, mips)});
    image_barrier(cmd, captured_.back(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, kNothing,
                  kNothing);
  }
  // A scene without probes still binds a cube array (of one black cube).
  array_.emplace(cube_image(gpu, name + " prefiltered cubes", size, mips, uint32_t(std::max<size_t>(count, 1))));
  image_barrier(cmd, *array_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kNothing,
                kTransferWrite);
  const VkClearColorValue zero{};
  const VkImageSubresourceRange range = array_->whole_range();
  vkCmdClearColorImage(cmd, array_->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  image_barrier(cmd, *array_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, kTransferWrite,
                kArrayReaders);
  return true;
}

void ProbeCubes::prefilter(PassContext& ctx, std::span<const uint32_t> probes, uint32_t samples) {
  if (probes.empty()) return;
  Context& gpu = ctx.gpu();
  VkCommandBuffer cmd = ctx.cmd();
  image_barrier(cmd, *array_, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                {kArrayReaders.stages, VK_ACCESS_2_NONE}, kTransferWrite);
  for (uint32_t i : probes) {
    Chain& c = chains_.at(i);
    for (Image* image : {&c.chain, &c.prefiltered})
      image_barrier(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, kEarlierPrefilter, kComputeWrite);
    record_specular_prefilter(gpu, ctx.pipelines(), cmd, ctx.pass().name + " prefilter", samples, captured_[i],
                              &c.chain, ctx.linear_sampler(), c.prefiltered, PrefilterSampling::filtered);
    image_barrier(cmd, c.prefiltered, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kComputeWrite,
                  kTransferRead);
    std::vector<VkImageCopy> copies;
    for (uint32_t mip = 0; mip < mips_; ++mip) {
      VkImageCopy copy{};
      copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 0, 6};
      copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mip, 6 * i, 6};
      const uint32_t m = std::max(1u, size_ >> mip);
      copy.extent = {m, m, 1};
      copies.push_back(copy);
    }
    vkCmdCopyImage(cmd, c.prefiltered.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, array_->handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(copies.size()), copies.data());
  }
  image_barrier(cmd, *array_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, kTransferWrite,
                kArrayReaders);
}

VkImageView ProbeCubes::cube_view(uint32_t probe) {
  return array_->view({.type = VK_IMAGE_VIEW_TYPE_CUBE, .base_layer = 6 * probe, .layer_count = 6});
}

}  // namespace lg
