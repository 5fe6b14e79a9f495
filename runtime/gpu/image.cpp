#include "runtime/gpu/image.h"

#include <utility>

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {
namespace {

bool has_depth(VkFormat f) {
  return f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_X8_D24_UNORM_PACK32 || f == VK_FORMAT_D32_SFLOAT ||
         f == VK_FORMAT_D16_UNORM_S8_UINT || f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

bool has_stencil(VkFormat f) {
  return f == VK_FORMAT_S8_UINT || f == VK_FORMAT_D16_UNORM_S8_UINT || f == VK_FORMAT_D24_UNORM_S8_UINT ||
         f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageCreateInfo create_info(const Context& context, const ImageDesc& desc) {
  auto fail = [&](const std::string& why) -> void { throw GpuError("image '" + desc.name + "': " + why); };
  auto info = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.imageType = desc.kind == ImageKind::image3d ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, desc.kind == ImageKind::image3d ? desc.depth : 1};
  info.mipLevels = desc.mips;
  info.arrayLayers = desc.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage ? desc.usage : supported_image_usage(context, desc.format);
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (desc.kind == ImageKind::cube) {
    if (desc.layers == 0 || desc.layers % 6 != 0) fail("a cube map needs layers in multiples of 6, not " + std::to_string(desc.layers));
    if (desc.width != desc.height) fail("cube faces must be square, not " + std::to_string(desc.width) + "x" + std::to_string(desc.height));
    info.flags |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  }
  if (desc.kind == ImageKind::image3d && desc.layers != 1) fail("a 3D image has one layer");

  VkImageFormatProperties limits;
  VkResult r = vkGetPhysicalDeviceImageFormatProperties(context.physical_device(), info.format, info.imageType,
                                                        info.tiling, info.usage, info.flags, &limits);
  if (r == VK_ERROR_FORMAT_NOT_SUPPORTED) fail("the device does not support its format with these usages");
  vk_check(r, "vkGetPhysicalDeviceImageFormatProperties", "for image '" + desc.name + "'");
  if (info.extent.width > limits.maxExtent.width || info.extent.height > limits.maxExtent.height ||
      info.extent.depth > limits.maxExtent.depth || info.mipLevels > limits.maxMipLevels ||
      info.arrayLayers > limits.maxArrayLayers)
    fail("its extent, mips or layers exceed the device's limits for its format (" +
         std::to_string(limits.maxExtent.width) + "x" + std::to_string(limits.maxExtent.height) + "x" +
         std::to_string(limits.maxExtent.depth) + ", " + std::to_string(limits.maxMipLevels) + " mips, " +
         std::to_string(limits.maxArrayLayers) + " layers)");
  return info;
}

}  // namespace

VkImageUsageFlags supported_image_usage(const Context& context, VkFormat format) {
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(context.physical_device(), format, &props);
  const VkFormatFeatureFlags f = props.optimalTilingFeatures;
  VkImageUsageFlags usage = 0;
  if (f & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (f & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) usage |= VK_IMAGE_USAGE_STORAGE_BIT;
  if (f & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (f & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (f & VK_FORMAT_FEATURE_TRANSFER_SRC_BIT) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (f & VK_FORMAT_FEATURE_TRANSFER_DST_BIT) usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  return usage;
}

Image::Image(Context& context, const ImageDesc& desc) : context_(&context), desc_(desc) {
  VkImageCreateInfo info = create_info(context, desc);
  vk_check(vkCreateImage(context.device(), &info, nullptr, &image_), "vkCreateImage", "for image '" + desc.name + "'");
  context.set_name(VK_OBJECT_TYPE_IMAGE, image_, desc.name);
}

Image Image::placed(Context& context, const ImageDesc& desc, const DeviceMemory& block, uint64_t offset,
                    uint64_t reserved) {
  Image image(context, desc);
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(context.device(), image.image_, &needs);
  check_placement(desc.name, needs, block, offset, reserved);
  image.bind(block.handle(), offset);
  return image;
}

Image Image::dedicated(Context& context, const ImageDesc& desc) {
  Image image(context, desc);
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(context.device(), image.image_, &needs);
  image.own_memory_ = DeviceMemory(context, needs.size, needs.memoryTypeBits, MemoryUse::device_local,
                                   "memory of image '" + desc.name + "'");
  image.bind(image.own_memory_.handle(), 0);
  return image;
}

VkMemoryRequirements Image::requirements(const Context& context, const ImageDesc& desc) {
  VkImageCreateInfo info = create_info(context, desc);
  auto query = vk_struct<VkDeviceImageMemoryRequirements>(VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS);
  query.pCreateInfo = &info;
  auto needs = vk_struct<VkMemoryRequirements2>(VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2);
  vkGetDeviceImageMemoryRequirements(context.device(), &query, &needs);
  return needs.memoryRequirements;
}

void Image::bind(VkDeviceMemory memory, uint64_t offset) {
  vk_check(vkBindImageMemory(context_->device(), image_, memory, offset), "vkBindImageMemory",
           "for image '" + desc_.name + "'");
  memory_ = memory;
  offset_ = offset;
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    desc_ = std::move(other.desc_);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    offset_ = other.offset_;
    own_memory_ = std::move(other.own_memory_);
    views_ = std::exchange(other.views_, {});
  }
  return *this;
}

void Image::release() {
  if (!image_) return;
  for (auto& [range, view] : views_) vkDestroyImageView(context_->device(), view, nullptr);
  views_.clear();
  vkDestroyImage(context_->device(), image_, nullptr);
  image_ = VK_NULL_HANDLE;
  own_memory_ = DeviceMemory();
}

VkImageAspectFlags Image::aspect() const {
  VkImageAspectFlags a = 0;
  if (has_depth(desc_.format)) a |= VK_IMAGE_ASPECT_DEPTH_BIT;
  if (has_stencil(desc_.format)) a |= VK_IMAGE_ASPECT_STENCIL_BIT;
  return a ? a : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT};
}

// Depth and stencil cannot be viewed or copied together; depth is what shaders read.
VkImageAspectFlags Image::primary_aspect() const {
  return has_depth(desc_.format) ? VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT} : aspect();
}

VkImageSubresourceRange Image::whole_range() const { return {aspect(), 0, desc_.mips, 0, desc_.layers}; }

VkImageView Image::view(const ViewRange& range) {
  for (const auto& [r, v] : views_)
    if (r == range) return v;
  const uint32_t mips = range.mip_count == VK_REMAINING_MIP_LEVELS ? desc_.mips - range.base_mip : range.mip_count;
  const uint32_t layers =
      range.layer_count == VK_REMAINING_ARRAY_LAYERS ? desc_.layers - range.base_layer : range.layer_count;
  VkImageViewType type = range.type;
  if (type == VK_IMAGE_VIEW_TYPE_MAX_ENUM) {
    switch (desc_.kind) {
      case ImageKind::image2d: type = layers == 1 ? VK_IMAGE_VIEW_TYPE_2D : VK_IMAGE_VIEW_TYPE_2D_ARRAY; break;
      case ImageKind::cube: type = layers == 6 ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_CUBE_ARRAY; break;
      case ImageKind::image3d: type = VK_IMAGE_VIEW_TYPE_3D; break;
    }
  }
  auto info = vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  info.image = image_;
  info.viewType = type;
  info.format = desc_.format;
  info.subresourceRange = {primary_aspect(), range.base_mip, mips, range.base_layer, layers};
  VkImageView view;
  vk_check(vkCreateImageView(context_->device(), &info, nullptr, &view), "vkCreateImageView",
           "for image '" + desc_.name + "'");
  views_.emplace_back(range, view);
  return view;
}

}  // namespace lg
