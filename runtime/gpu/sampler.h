// Samplers: linear or nearest filtering, clamped, repeating or mirrored addresses, over every
// mip or mip 0 only, with anisotropic filtering where the device enabled it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

namespace lg {

class Context;

enum class Filter : uint8_t { nearest, linear };
enum class Address : uint8_t { clamp, repeat, mirrored_repeat };

struct SamplerDesc {
  Filter filter = Filter::linear;    // magnification, and minification and between mips unless set below
  Address address = Address::clamp;  // along u, and v unless address_v is set
  // What materials' samplers set apart (glTF allows each its own).
  std::optional<Filter> min_filter{}, mip_filter{};
  std::optional<Address> address_v{};
  bool mip_0_only = false;
  // Up to this many samples along the footprint; above 1 only on a device that enabled
  // samplerAnisotropy (Context::max_sampler_anisotropy()), clamped to its limit.
  float max_anisotropy = 1.0f;
};

class Sampler {
 public:
  Sampler(Context& context, const SamplerDesc& desc);
  ~Sampler();
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;

  VkSampler handle() const { return sampler_; }

 private:
  Context& context_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace lg
