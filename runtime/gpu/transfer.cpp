#include "runtime/gpu/transfer.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "runtime/gpu/buffer.h"
#include "runtime/gpu/context.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/submit.h"
#include "runtime/gpu/texel_codec.h"

namespace lg {
namespace {

VkBufferImageCopy copy_region(const Image& image, ImageLocation where) {
  const ImageDesc& d = image.desc();
  if (where.mip >= d.mips || (d.kind != ImageKind::image3d && where.layer >= d.layers))
    throw GpuError("image '" + d.name + "' has no mip " + std::to_string(where.mip) + " layer " +
                   std::to_string(where.layer));
  VkBufferImageCopy region{};
  region.imageSubresource = {image.primary_aspect(), where.mip, d.kind == ImageKind::image3d ? 0 : where.layer, 1};
  region.imageExtent = {std::max(1u, d.width >> where.mip), std::max(1u, d.height >> where.mip),
                        d.kind == ImageKind::image3d ? std::max(1u, d.depth >> where.mip) : 1};
  return region;
}

Buffer staging(Submitter& submitter, const std::string& what, uint64_t bytes, MemoryUse use) {
  return Buffer::dedicated(
      submitter.context(),
      {"staging for " + what, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT}, use);
}

// One region per mip, each covering every layer, packed in that order.
std::vector<VkBufferImageCopy> whole_image_regions(const Image& image) {
  const ImageDesc& d = image.desc();
  const bool volume = d.kind == ImageKind::image3d;
  std::vector<VkBufferImageCopy> regions;
  uint64_t offset = 0;
  for (uint32_t mip = 0; mip < d.mips; ++mip) {
    VkBufferImageCopy& region = regions.emplace_back(copy_region(image, {mip, 0}));
    region.bufferOffset = offset;
    region.imageSubresource.layerCount = volume ? 1 : d.layers;
    offset += texel_count(image, mip) * (volume ? 1 : d.layers) * format_info(d.format).bytes_per_texel;
  }
  return regions;
}

}  // namespace

uint64_t image_byte_size(const Image& image) {
  const ImageDesc& d = image.desc();
  uint64_t texels = 0;
  for (uint32_t mip = 0; mip < d.mips; ++mip) texels += texel_count(image, mip);
  return texels * (d.kind == ImageKind::image3d ? 1 : d.layers) * format_info(d.format).bytes_per_texel;
}

std::vector<std::byte> read_image_bytes(Submitter& submitter, const Image& image, VkImageLayout layout) {
  if (layout == VK_IMAGE_LAYOUT_UNDEFINED)
    throw GpuError("reading image '" + image.desc().name + "' in the UNDEFINED layout: it holds nothing yet");
  const uint64_t size = image_byte_size(image);
  const std::vector<VkBufferImageCopy> regions = whole_image_regions(image);
  Buffer stage = staging(submitter, "image '" + image.desc().name + "'", size, MemoryUse::readback);
  submitter.run([&](VkCommandBuffer cmd) {
    image_barrier(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage.handle(),
                           uint32_t(regions.size()), regions.data());
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
    memory_barrier(cmd, {}, {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT});  // to the host
  });
  std::vector<std::byte> out(size);
  std::memcpy(out.data(), stage.mapped(), size);
  return out;
}

void upload_image_bytes(Submitter& submitter, const Image& image, std::span<const std::byte> bytes,
                        VkImageLayout new_layout) {
  const uint64_t size = image_byte_size(image);
  if (bytes.size() != size)
    throw GpuError("upload to image '" + image.desc().name + "': " + std::to_string(bytes.size()) + " bytes given, " +
                   std::to_string(size) + " expected");
  const std::vector<VkBufferImageCopy> regions = whole_image_regions(image);
  Buffer stage = staging(submitter, "image '" + image.desc().name + "'", size, MemoryUse::upload);
  std::memcpy(stage.mapped(), bytes.data(), size);
  submitter.run([&](VkCommandBuffer cmd) {
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(cmd, stage.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, new_layout);
  });
}

uint64_t texel_count(const Image& image, uint32_t mip) {
  const ImageDesc& d = image.desc();
  const uint64_t depth = d.kind == ImageKind::image3d ? std::max(1u, d.depth >> mip) : 1;
  return uint64_t{std::max(1u, d.width >> mip)} * std::max(1u, d.height >> mip) * depth;
}

void upload_image(Submitter& submitter, const Image& image, std::span<const float> rgba, VkImageLayout new_layout,
                  ImageLocation where, VkImageLayout old_layout) {
  const FormatInfo& format = format_info(image.desc().format);
  const VkBufferImageCopy region = copy_region(image, where);
  const uint64_t texels = texel_count(image, where.mip);
  if (rgba.size() != texels * 4)
    throw GpuError("upload to image '" + image.desc().name + "': " + std::to_string(rgba.size()) + " floats given, " +
                   std::to_string(texels * 4) + " expected (4 per texel)");
  Buffer stage =
      staging(submitter, "image '" + image.desc().name + "'", texels * format.bytes_per_texel, MemoryUse::upload);
  encode_texels(format, rgba, {stage.mapped(), texels * format.bytes_per_texel});
  submitter.run([&](VkCommandBuffer cmd) {
    image_barrier(cmd, image, old_layout, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    vkCmdCopyBufferToImage(cmd, stage.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, new_layout);
  });
}

std::vector<float> read_image(Submitter& submitter, const Image& image, VkImageLayout layout, ImageLocation where) {
  if (layout == VK_IMAGE_LAYOUT_UNDEFINED)
    throw GpuError("reading image '" + image.desc().name + "' in the UNDEFINED layout: it holds nothing yet");
  const FormatInfo& format = format_info(image.desc().format);
  const VkBufferImageCopy region = copy_region(image, where);
  const uint64_t texels = texel_count(image, where.mip);
  Buffer stage =
      staging(submitter, "image '" + image.desc().name + "'", texels * format.bytes_per_texel, MemoryUse::readback);
  submitter.run([&](VkCommandBuffer cmd) {
    image_barrier(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage.handle(), 1, &region);
    image_barrier(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
    memory_barrier(cmd, {}, {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT});  // to the host
  });
  std::vector<float> rgba(texels * 4);
  decode_texels(format, {stage.mapped(), texels * format.bytes_per_texel}, rgba);
  return rgba;
}

void upload_buffer(Submitter& submitter, const Buffer& buffer, std::span<const std::byte> bytes, uint64_t offset) {
  if (offset + bytes.size() > buffer.size())
    throw GpuError("upload of " + std::to_string(bytes.size()) + " bytes at offset " + std::to_string(offset) +
                   " runs past the end of buffer '" + buffer.desc().name + "' (" + std::to_string(buffer.size()) +
                   " bytes)");
  if (bytes.empty()) return;
  Buffer stage = staging(submitter, "buffer '" + buffer.desc().name + "'", bytes.size(), MemoryUse::upload);
  std::memcpy(stage.mapped(), bytes.data(), bytes.size());
  submitter.run([&](VkCommandBuffer cmd) {
    memory_barrier(cmd);
    const VkBufferCopy region{0, offset, bytes.size()};
    vkCmdCopyBuffer(cmd, stage.handle(), buffer.handle(), 1, &region);
    memory_barrier(cmd);
  });
}

std::vector<std::byte> read_buffer(Submitter& submitter, const Buffer& buffer, uint64_t offset, uint64_t size) {
  if (size == VK_WHOLE_SIZE) size = offset < buffer.size() ? buffer.size() - offset : 0;
  if (offset + size > buffer.size())
    throw GpuError("reading " + std::to_string(size) + " bytes at offset " + std::to_string(offset) +
                   " runs past the end of buffer '" + buffer.desc().name + "' (" + std::to_string(buffer.size()) +
                   " bytes)");
  std::vector<std::byte> out(size);
  if (size == 0) return out;
  Buffer stage = staging(submitter, "buffer '" + buffer.desc().name + "'", size, MemoryUse::readback);
  submitter.run([&](VkCommandBuffer cmd) {
    memory_barrier(cmd, {}, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
    const VkBufferCopy region{offset, 0, size};
    vkCmdCopyBuffer(cmd, buffer.handle(), stage.handle(), 1, &region);
    memory_barrier(cmd, {}, {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT});  // to the host
  });
  std::memcpy(out.data(), stage.mapped(), size);
  return out;
}

}  // namespace lg
