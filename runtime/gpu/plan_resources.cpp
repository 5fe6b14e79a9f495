#include "runtime/gpu/plan_resources.h"

#include "runtime/gpu/context.h"
#include "runtime/gpu/format.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

ImageDesc image_desc(const LoweredResource& resource) {
  if (resource.kind == ResourceKind::buffer) throw GpuError("'" + resource.name + "' is a buffer, not an image");
  ImageDesc d;
  d.name = resource.name;
  d.format = vk_format(resource.format);
  d.width = resource.width;
  d.height = resource.height;
  d.mips = resource.mips;
  d.layers = resource.layers;
  switch (resource.kind) {
    case ResourceKind::texture2d: d.kind = ImageKind::image2d; break;
    case ResourceKind::cube: d.kind = ImageKind::cube; break;
    case ResourceKind::texture3d:
      d.kind = ImageKind::image3d;
      d.depth = resource.layers;
      d.layers = 1;
      break;
    case ResourceKind::buffer: break;
  }
  return d;
}

BufferDesc buffer_desc(const LoweredResource& resource) {
  if (resource.kind != ResourceKind::buffer) throw GpuError("'" + resource.name + "' is an image, not a buffer");
  return {resource.name, resource.bytes};
}

ResourceMemory device_memory_needs(const Context& context, const LoweredResource& resource) {
  if (resource.kind != ResourceKind::buffer) {
    const VkMemoryRequirements needs = Image::requirements(context, image_desc(resource));
    return {needs.size, needs.alignment};
  }
  auto info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  const BufferDesc desc = buffer_desc(resource);
  info.size = desc.size;
  info.usage = desc.usage;
  auto query = vk_struct<VkDeviceBufferMemoryRequirements>(VK_STRUCTURE_TYPE_DEVICE_BUFFER_MEMORY_REQUIREMENTS);
  query.pCreateInfo = &info;
  auto needs = vk_struct<VkMemoryRequirements2>(VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2);
  vkGetDeviceBufferMemoryRequirements(context.device(), &query, &needs);
  return {needs.memoryRequirements.size, needs.memoryRequirements.alignment};
}

AliasOptions device_alias_options(const Context& context) {
  AliasOptions options;
  options.memory = [&context](const LoweredResource& r) { return device_memory_needs(context, r); };
  return options;
}

}  // namespace lg
