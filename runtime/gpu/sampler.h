// Samplers: linear or nearest filtering, clamped or repeating addresses, over every mip.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace lg {

class Context;

enum class Filter : uint8_t { nearest, linear };
enum class Address : uint8_t { clamp, repeat };

struct SamplerDesc {
  Filter filter = Filter::linear;  // also between mips
  Address address = Address::clamp;
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
