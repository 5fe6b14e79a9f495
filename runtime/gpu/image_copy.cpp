#include "runtime/gpu/image_copy.h"

#include <algorithm>
#include <vector>

#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"

namespace lg {

void copy_image(VkCommandBuffer cmd, const Image& from, VkImageLayout from_layout, const Image& to,
                VkImageLayout to_layout) {
  image_barrier(cmd, from, from_layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  image_barrier(cmd, to, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  const ImageDesc& d = from.desc();
  std::vector<VkImageCopy> regions;
  for (uint32_t mip = 0; mip < d.mips; ++mip) {
    VkImageCopy region{};
    region.srcSubresource = {from.primary_aspect(), mip, 0, d.layers};
    region.dstSubresource = region.srcSubresource;
    region.extent = {std::max(d.width >> mip, 1u), std::max(d.height >> mip, 1u), std::max(d.depth >> mip, 1u)};
    regions.push_back(region);
  }
  vkCmdCopyImage(cmd, from.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, to.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()), regions.data());
  image_barrier(cmd, from, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, from_layout);
  image_barrier(cmd, to, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, to_layout);
}

}  // namespace lg
