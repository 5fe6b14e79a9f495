#include "nodes/gi/irradiance_volume/probe_atlas_images.h"

#include <vector>

#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/texel_codec.h"

namespace lg {
namespace {

// graph/port_type.cpp sizes the plan's probe_volume buffer (the `probes` output) as 64 x 160
// bytes, without this header; copy_volumes() writes the whole block into it.
static_assert(kMaxProbeVolumes * sizeof(GpuProbeVolume) == 64 * 160,
              "graph/port_type.cpp's probe_volume size must hold the volumes' block");

struct Target {
  std::optional<Image>* image;
  const AtlasImage* source;
  VkFormat format;
  const char* what;
};

}  // namespace

ProbeAtlasImages::ProbeAtlasImages(Context& gpu, std::string name)
    : gpu_(gpu),
      name_(std::move(name)),
      volumes_(gpu, name_ + " volumes", VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
      staging_(gpu, name_ + " atlas staging", VK_BUFFER_USAGE_TRANSFER_SRC_BIT) {}

void ProbeAtlasImages::upload(VkCommandBuffer cmd, const ProbeAtlas& atlas) {
  // The shader declares kMaxProbeVolumes of them: the buffer holds that many.
  block_ = atlas.volumes;
  block_.resize(kMaxProbeVolumes);
  volumes_.write(block_);
  const Target targets[] = {{&records_, &atlas.records, VK_FORMAT_R32G32B32A32_SFLOAT, "records"},
                            {&irradiance_, &atlas.irradiance, VK_FORMAT_R16G16B16A16_SFLOAT, "irradiance"},
                            {&distance_, &atlas.distance, VK_FORMAT_R32G32_SFLOAT, "distance"}};
  // Every image's texels in the image's format, one after the other in the staging buffer.
  std::vector<std::byte> bytes;
  std::vector<uint64_t> offsets;
  for (const Target& t : targets) {
    const FormatInfo& format = format_info(t.format);
    offsets.push_back(bytes.size());
    const size_t texels = size_t(t.source->width) * t.source->height;
    bytes.resize(bytes.size() + texels * format.bytes_per_texel);
    encode_texels(format, t.source->rgba, std::span(bytes).subspan(offsets.back()));
    const bool same =
        *t.image && (*t.image)->desc().width == t.source->width && (*t.image)->desc().height == t.source->height;
    if (!same)
      t.image->emplace(Image::dedicated(gpu_, {.name = name_ + " probe " + t.what,
                                               .format = t.format,
                                               .width = t.source->width,
                                               .height = t.source->height,
                                               .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}));
  }
  staging_.write(bytes);
  for (size_t i = 0; i < std::size(targets); ++i) {
    const Image& image = **targets[i].image;
    // Earlier frames' reads are finished (the executor waits for each frame), so the old
    // contents are dropped without waiting on them.
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE},
                  {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
    VkBufferImageCopy region{};
    region.bufferOffset = offsets[i];
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {image.desc().width, image.desc().height, 1};
    vkCmdCopyBufferToImage(cmd, staging_.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL,
                  {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                  {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
  }
}

void ProbeAtlasImages::copy_volumes(VkCommandBuffer cmd, VkBuffer target) const {
  // After the plan's barrier into compute shaders (a chained dependency), and back to them.
  memory_barrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE},
                 {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  vkCmdUpdateBuffer(cmd, target, 0, block_.size() * sizeof(GpuProbeVolume), block_.data());
  memory_barrier(
      cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
      {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
       VK_ACCESS_2_UNIFORM_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}

}  // namespace lg
