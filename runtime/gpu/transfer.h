// Moving data between the host and the GPU through staging buffers: images as float RGBA
// (converted to and from the image's format), buffers as bytes. Each call submits and waits.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace lg {

class Buffer;
class Image;
class Submitter;

// One mip level of one layer; a 3D image's mip is its whole volume (the layer is ignored).
struct ImageLocation {
  uint32_t mip = 0, layer = 0;
};

// Texels of that mip: width x height (x depth) of them.
uint64_t texel_count(const Image& image, uint32_t mip);

// Writes `rgba` (4 floats per texel, row by row, then slice by slice) into `where`, moving the
// image from `old_layout` to `new_layout` (the rest of the image too).
void upload_image(Submitter& submitter, const Image& image, std::span<const float> rgba, VkImageLayout new_layout,
                  ImageLocation where = {}, VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED);

// Reads `where` as float RGBA; the image is in `layout` (not UNDEFINED) before and after.
std::vector<float> read_image(Submitter& submitter, const Image& image, VkImageLayout layout, ImageLocation where = {});

// Every mip and layer of an image as the format stores them, mip after mip (a mip's layers, or
// its 3D slices, back to back): for keeping results byte for byte, with no float conversion.
uint64_t image_byte_size(const Image& image);
std::vector<std::byte> read_image_bytes(Submitter& submitter, const Image& image, VkImageLayout layout);
// Writes those bytes (image_byte_size of them), moving the image from UNDEFINED to `new_layout`.
void upload_image_bytes(Submitter& submitter, const Image& image, std::span<const std::byte> bytes,
                        VkImageLayout new_layout);

void upload_buffer(Submitter& submitter, const Buffer& buffer, std::span<const std::byte> bytes, uint64_t offset = 0);
std::vector<std::byte> read_buffer(Submitter& submitter, const Buffer& buffer, uint64_t offset = 0,
                                   uint64_t size = VK_WHOLE_SIZE);

}  // namespace lg
