// Images: 2D (with mips and layers), cube maps (layers in sixes) and 3D, either placed in a
// plan memory block at the plan's offset or given their own memory; their views, made on
// demand and kept with the image.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/gpu/memory.h"

namespace lg {

class Context;

enum class ImageKind : uint8_t { image2d, cube, image3d };

struct ImageDesc {
  std::string name{};  // in errors and validation messages: "gbuf.gbuffer.normal"
  ImageKind kind = ImageKind::image2d;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  uint32_t width = 1, height = 1, depth = 1;  // depth: 3D images only
  uint32_t mips = 1;
  uint32_t layers = 1;  // cube maps: 6 per cube
  // 0: every usage the format supports among sampled, storage, colour or depth attachment
  // and transfer, so aliased images and any pass can use it.
  VkImageUsageFlags usage = 0;
};

// The usages `format` supports as an optimally tiled image, among those listed for ImageDesc.
VkImageUsageFlags supported_image_usage(const Context& context, VkFormat format);

// Which part of an image a view shows. VK_IMAGE_VIEW_TYPE_MAX_ENUM picks the natural type:
// 2D, 2D array, cube, cube array or 3D.
struct ViewRange {
  VkImageViewType type = VK_IMAGE_VIEW_TYPE_MAX_ENUM;
  uint32_t base_mip = 0, mip_count = VK_REMAINING_MIP_LEVELS;
  uint32_t base_layer = 0, layer_count = VK_REMAINING_ARRAY_LAYERS;
  friend bool operator==(const ViewRange&, const ViewRange&) = default;
};

class Image {
 public:
  // Bound at `offset` of a plan block whose placement reserves `reserved` bytes; throws
  // GpuError naming the image if its memory requirements do not fit there.
  static Image placed(Context& context, const ImageDesc& desc, const DeviceMemory& block, uint64_t offset,
                      uint64_t reserved);
  // With memory of its own.
  static Image dedicated(Context& context, const ImageDesc& desc);
  // What the device needs for such an image, without creating one.
  static VkMemoryRequirements requirements(const Context& context, const ImageDesc& desc);

  Image() = default;
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;

  VkImage handle() const { return image_; }
  const ImageDesc& desc() const { return desc_; }
  VkImageAspectFlags aspect() const;          // every aspect: for barriers
  VkImageAspectFlags primary_aspect() const;  // depth for depth formats, else colour: for views and copies
  VkImageSubresourceRange whole_range() const;  // every mip and layer
  VkDeviceMemory memory() const { return memory_; }
  uint64_t memory_offset() const { return offset_; }

  // A view of `range`, created on first use and destroyed with the image.
  VkImageView view(const ViewRange& range = {});

 private:
  Image(Context& context, const ImageDesc& desc);  // created, not bound
  void bind(VkDeviceMemory memory, uint64_t offset);
  void release();

  Context* context_ = nullptr;
  ImageDesc desc_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  uint64_t offset_ = 0;
  DeviceMemory own_memory_;  // dedicated images only
  std::vector<std::pair<ViewRange, VkImageView>> views_;
};

}  // namespace lg
