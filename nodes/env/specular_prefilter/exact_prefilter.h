// env.specular_prefilter's exact method: each output texel a sum over texels of the environment
// (shaders/prefilter_exact.comp) rather than over random samples, from levels of the node's
// chain (shaders/prefilter_exact_chain.comp) chosen per roughness, with the environment's peaks
// (a sun) in a list summed exactly at their own directions.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace lg {

class Buffer;
class Context;
class Image;
class PipelineCache;

// Which levels of the chain one output mip sums, by face size: every texel of the `coarse` level
// except those whose centres lie within `near_angle` (radians) of the output direction, which
// are summed on the `fine` level (near_angle 0: coarse only).
struct ExactPrefilterLevels {
  uint32_t coarse = 0, fine = 0;
  double near_angle = 0;
};
ExactPrefilterLevels exact_prefilter_levels(double alpha, uint32_t env_size);

// The peak list holds at most this many texels (a texel past it stays in the chain): 16 KiB,
// the least maxUniformBufferRange a device may have (the sums read it as a uniform buffer).
// On 128^2 cubes grace.hdr has 407 peaks, the random environment 72, pisa.hdr none.
inline constexpr uint32_t kPrefilterPeakCapacity = 511;
// The peak list's size in bytes (a count, the capacity, then two vec4 per peak).
uint64_t prefilter_peaks_bytes();

// Records every mip of `prefiltered` (rgba16f cube, GENERAL) from `env` (a cube with its mips,
// READ_ONLY_OPTIMAL; its last mip must be its mean, as env.load's area-correct chain is): first
// `chain` (rgba16f cube, env's face size, every mip, GENERAL) and the list in `peaks` (at least
// prefilter_peaks_bytes(), storage), then the sums.
void record_specular_prefilter_exact(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd,
                                     const std::string& name, Image& env, Image& chain, VkSampler sampler,
                                     const Buffer& peaks, Image& prefiltered);

}  // namespace lg
