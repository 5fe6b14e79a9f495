#include "nodes/env/specular_prefilter/exact_prefilter.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "nodes/common/compute.h"
#include "nodes/common/node_shaders.h"
#include "nodes/env/specular_prefilter/specular_prefilter_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/descriptors.h"
#include "runtime/gpu/direct_barriers.h"
#include "runtime/gpu/image.h"
#include "runtime/gpu/pipeline.h"

namespace lg {
namespace {

constexpr uint32_t kGroup = 8;
// The peaks are taken from the chain's first level of at most this face size.
constexpr uint32_t kPeakFace = 128;
static_assert(kPrefilterPeakCapacity == 511, "shaders/prefilter_exact.comp's Peaks block holds 511 peaks");
static_assert(16 + kPrefilterPeakCapacity * 32 <= 16384, "the peak list must fit the least maxUniformBufferRange");

struct ChainPush {  // shaders/prefilter_exact_chain.comp
  uint32_t first, peak_level;
};

struct SumPush {  // shaders/prefilter_exact.comp
  float alpha;
  int32_t coarse_level, fine_level;
  float cos_near;
};

int32_t level_of(uint32_t env_size, uint32_t face) {
  return std::countr_zero(env_size / face);
}

}  // namespace

// Chosen in a double-precision emulation of the sums (box levels as the shaders make them, peaks
// above 16x the mean; the node now lists those above 32x, so grace's fit the list, and the GPU's
// errors with it are in the README) against the brute force, RMS relative error over 150 random output texels
// on a 128^2 random environment, grace.hdr and pisa.hdr (worst of the three), with the texels
// summed per output texel:
// - the coarse level, 16^2 a face, alone: 0.13% at roughness 0.75 and 1 (8^2 a face: 0.60%;
//   32^2: 0.03% for 4x the work);
// - below alpha 0.5 the lobe curves too fast near its peak for 16^2 texels (roughness 0.5:
//   0.26%, 0.25: 2.6%), so the coarse texels within the near cap, 8 alpha but 0.5 to 1 radian,
//   are summed on the level whose faces are 2.5 / alpha wide, at least 32: roughness 0.5 (32^2,
//   1 rad) 0.053% in 2,600 texels, 0.25 (64^2, 0.5 rad) 0.11% in 3,000, 0.2 (64^2) 0.18% (128^2:
//   0.08% in 7,800), 0.4 (32^2) 0.08%, 0.6 (32^2) 0.07%. A smaller cap or a coarser fine level
//   raised the error fast (roughness 0.25 with a 0.25 rad cap 0.53%, roughness 0.2 on 32^2 0.9%).
// Without the peak list the coarse sums miss by far more: grace at roughness 0.5 on 16^2 3.3%.
ExactPrefilterLevels exact_prefilter_levels(double alpha, uint32_t env_size) {
  const uint32_t coarse = std::min(16u, env_size);
  ExactPrefilterLevels levels{coarse, coarse, 0.0};
  if (alpha >= 0.5) return levels;
  // At most 8x the coarse faces: lavapipe ends an invocation's loops after 65535 iterations in
  // all, and a 0.5 rad cap holds about 300 coarse texels of 16^2 a face, 64 children each (a
  // 1 rad cap, which alpha >= 0.125 takes, goes with 2.5 / alpha <= 32). Above 128^2 a face this
  // leaves alpha under 2.5 / 128 (roughness under 0.14) with a fine level coarser than it wants.
  const uint32_t wanted = std::bit_ceil(uint32_t(std::ceil(2.5 / std::max(alpha, 1e-3))));
  const uint32_t fine = std::min({std::max(wanted, 2 * coarse), 8 * coarse, env_size});
  static_assert(8 * 16 <= kPeakFace, "the sums must not read levels above the one the peaks are taken from");
  if (fine <= coarse) return levels;
  levels.fine = fine;
  levels.near_angle = std::clamp(8.0 * alpha, 0.5, 1.0);
  return levels;
}

uint64_t prefilter_peaks_bytes() {
  return 16 + uint64_t(kPrefilterPeakCapacity) * 32;
}

void record_specular_prefilter_exact(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd,
                                     const std::string& name, Image& env, Image& chain, VkSampler sampler,
                                     const Buffer& peaks, Image& prefiltered) {
  const uint32_t env_size = env.desc().width;
  if (chain.desc().width != env_size || chain.desc().mips != env.desc().mips)
    throw std::invalid_argument("env.specular_prefilter: the chain (" + std::to_string(chain.desc().width) + "^2, " +
                                std::to_string(chain.desc().mips) + " mips) differs from the environment (" +
                                std::to_string(env_size) + "^2, " + std::to_string(env.desc().mips) + " mips)");
  if (!std::has_single_bit(env_size))
    throw std::invalid_argument("env.specular_prefilter: the environment's faces (" + std::to_string(env_size) +
                                ") are not a power of two");
  if (peaks.size() < prefilter_peaks_bytes())
    throw std::invalid_argument("env.specular_prefilter: the peak list holds " + std::to_string(peaks.size()) +
                                " bytes, not " + std::to_string(prefilter_peaks_bytes()));

  // The list's count to 0 and its capacity, after any earlier use of the buffer.
  memory_barrier(cmd);
  vkCmdFillBuffer(cmd, peaks.handle(), 0, 4, 0);
  vkCmdFillBuffer(cmd, peaks.handle(), 4, 4, kPrefilterPeakCapacity);
  memory_barrier(cmd, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                 {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});

  const Pipeline& chain_pipeline =
      pipelines.compute({name,
                         node_shader("nodes/env/specular_prefilter/shaders/prefilter_exact_chain.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                          {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                          {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                          {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                         sizeof(ChainPush)});
  for (uint32_t mip = 0; mip < chain.desc().mips; ++mip) {
    if (mip > 0) compute_to_compute_barrier(cmd);
    const uint32_t size = std::max(1u, env_size >> mip);
    const DescriptorWrite writes[] = {
        mip == 0
            ? sampled_image(0, env.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = 0, .mip_count = 1}), sampler)
            : sampled_image(0, chain.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip - 1, .mip_count = 1}),
                            sampler, VK_IMAGE_LAYOUT_GENERAL),
        storage_image(1, chain.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1})),
        sampled_image(2, env.view(), sampler), storage_buffer(3, peaks.handle())};
    bind_pipeline(gpu, cmd, chain_pipeline, writes);
    push_constants(cmd, chain_pipeline, ChainPush{mip == 0 ? 1u : 0u, size == std::min(env_size, kPeakFace) ? 1u : 0u});
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
  // The sums read the chain sampled and the peak list as a uniform buffer.
  memory_barrier(
      cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
      {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT});

  const Pipeline& sum_pipeline =
      pipelines.compute({name,
                         node_shader("nodes/env/specular_prefilter/shaders/prefilter_exact.comp"),
                         {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                          {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                          {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                          {3, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                         sizeof(SumPush)});
  const uint32_t mips = prefiltered.desc().mips;
  for (uint32_t mip = 0; mip < mips; ++mip) {
    const uint32_t size = std::max(1u, prefiltered.desc().width >> mip);
    const double roughness = prefilter_roughness(mip, mips), alpha = roughness * roughness;
    const ExactPrefilterLevels levels = exact_prefilter_levels(alpha, env_size);
    const DescriptorWrite writes[] = {
        sampled_image(0, chain.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY}), sampler, VK_IMAGE_LAYOUT_GENERAL),
        storage_image(1, prefiltered.view({.type = VK_IMAGE_VIEW_TYPE_2D_ARRAY, .base_mip = mip, .mip_count = 1})),
        sampled_image(2, env.view(), sampler), uniform_buffer(3, peaks.handle(), 0, prefilter_peaks_bytes())};
    bind_pipeline(gpu, cmd, sum_pipeline, writes);
    push_constants(cmd, sum_pipeline,
                   SumPush{float(alpha), level_of(env_size, levels.coarse), level_of(env_size, levels.fine),
                           levels.near_angle > 0 ? float(std::cos(levels.near_angle)) : 2.0f});
    vkCmdDispatch(cmd, (size + kGroup - 1) / kGroup, (size + kGroup - 1) / kGroup, 6);
  }
}

}  // namespace lg
