// The kernel of env.sh_project, and the passes it records (which tests run directly): the
// environment projected onto real SH (nodes/env/common/sh_basis.h, docs/env-conventions.md)
// with exact texel solid angles, windowed and optionally convolved with the cosine lobe. Two
// dispatches: blocks of 2048 texels into partial sums (a scratch buffer the kernel owns), then
// one workgroup adds them up. Mip 0 is projected; of faces over 1024, the 1024 mip (lavapipe's
// loop budget; the area-correct mips keep the integral and bands <= 4 barely vary over a texel).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "nodes/env/common/sh_basis.h"
#include "runtime/exec/node_kernel.h"

namespace lg {

inline constexpr uint32_t kShProjectMaxFace = 1024;

struct ShProjectSettings {
  int order = 2;
  std::vector<double> band_factors;  // per band: window times (cosine lobe when convolving, else 1)
};

ShProjectSettings sh_project_settings(int order, ShWindow window, double window_target, bool convolve_cosine);

// The mip of `env` that is projected, and the bytes of scratch its blocks need.
uint32_t sh_project_mip(const Image& env);
uint64_t sh_partials_bytes(const Image& env);

// Records the projection of `env` (a cube map in READ_ONLY_OPTIMAL) into `coefficients`
// (sh_count(order) vec4s: RGB and, in coefficient 0's w, the number of non-finite texels,
// which count as 0), through `partials` (at least sh_partials_bytes(env)).
void record_sh_project(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                       const ShProjectSettings& settings, Image& env, VkSampler sampler, const Buffer& partials,
                       const Buffer& coefficients);

std::unique_ptr<NodeKernel> make_sh_project_kernel(const PlanNode& node);

}  // namespace lg
