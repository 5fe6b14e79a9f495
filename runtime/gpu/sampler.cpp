#include "runtime/gpu/sampler.h"

#include <algorithm>

#include "runtime/gpu/context.h"
#include "runtime/gpu/gpu_error.h"
#include "runtime/gpu/vk_struct.h"

namespace lg {

namespace {

VkSamplerAddressMode address_mode(Address a) {
  switch (a) {
    case Address::repeat:
      return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case Address::mirrored_repeat:
      return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case Address::clamp:
      break;
  }
  return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
}

VkFilter filter_mode(Filter f) {
  return f == Filter::linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
}

}  // namespace

Sampler::Sampler(Context& context, const SamplerDesc& desc) : context_(context) {
  auto info = vk_struct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = filter_mode(desc.filter);
  info.minFilter = filter_mode(desc.min_filter.value_or(desc.filter));
  info.mipmapMode = desc.mip_filter.value_or(desc.filter) == Filter::linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                                            : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeW = address_mode(desc.address);
  info.addressModeV = address_mode(desc.address_v.value_or(desc.address));
  info.maxLod = desc.mip_0_only ? 0.0f : VK_LOD_CLAMP_NONE;
  const float anisotropy = std::min(desc.max_anisotropy, context.max_sampler_anisotropy());
  info.anisotropyEnable = anisotropy > 1.0f;
  info.maxAnisotropy = info.anisotropyEnable ? anisotropy : 1.0f;
  vk_check(vkCreateSampler(context.device(), &info, nullptr, &sampler_), "vkCreateSampler");
}

Sampler::~Sampler() {
  vkDestroySampler(context_.device(), sampler_, nullptr);
}

}  // namespace lg
