// The kernel of env.specular_prefilter, and the pass it records (which tests run directly): the
// environment prefiltered by GGX for the split sum, mip m of the output holding roughness
// m / (mips - 1) (a single mip holds roughness 0).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>

#include "runtime/exec/node_kernel.h"

namespace lg {

// lavapipe ends an invocation's loops after 65535 iterations in all: more samples are clamped.
inline constexpr uint32_t kMaxPrefilterSamples = 32768;

// The perceptual roughness mip `mip` of a `mips`-level prefiltered map holds.
inline double prefilter_roughness(uint32_t mip, uint32_t mips) {
  return mips > 1 ? double(mip) / (mips - 1) : 0.0;
}

// filtered: each sample reads the mip matching its solid angle (what the node does); plain_mip0:
// every sample reads mip 0 (plain GGX importance sampling, the benchmark's baseline).
enum class PrefilterSampling { filtered, plain_mip0 };

// Records every mip of `prefiltered` (rgba16f cube, in GENERAL) from `env` (a cube map with its
// mips, in READ_ONLY_OPTIMAL), read through `trilinear`. Filtered sampling first builds its own
// mip chain of env's mip 0 in `chain` (rgba16f cube, env's face size, every mip down to 1x1, in
// GENERAL; the node's tmp.chain), smoother than env's box chain, and reads that; plain sampling
// reads env's mip 0 and takes no chain (nullptr).
void record_specular_prefilter(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                               uint32_t samples, Image& env, Image* chain, VkSampler trilinear, Image& prefiltered,
                               PrefilterSampling sampling);

std::unique_ptr<NodeKernel> make_specular_prefilter_kernel(const PlanNode& node);

}  // namespace lg
