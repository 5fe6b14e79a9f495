#include "runtime/gpu/sampler.h"

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

Sampler::Sampler(Context& context, const SamplerDesc& desc) : context_(context) {
  const bool linear = desc.filter == Filter::linear;
  const VkSamplerAddressMode address =
      desc.address == Address::clamp ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
  auto info = vk_struct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = info.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  info.mipmapMode = linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = address;
  info.maxLod = VK_LOD_CLAMP_NONE;
  vk_check(vkCreateSampler(context.device(), &info, nullptr, &sampler_), "vkCreateSampler");
}

Sampler::~Sampler() { vkDestroySampler(context_.device(), sampler_, nullptr); }

}  // namespace lg
