// The kernel of env.irradiance, and the pass it records (which tests run directly): irradiance
// / pi by direct cosine convolution over one mip of the environment.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/image.h"

namespace lg {

// The lights the convolution sums have faces of `env`'s face >> source_mip texels, at most 64:
// lavapipe ends an invocation's loops after 65535 iterations in all (6 x 64^2 lights). Each is
// summed from at most 64 x 64 texels of the finest mip that allows (irradiance_sources.comp).
inline constexpr uint32_t kIrradianceMaxSourceFace = 64;
uint32_t irradiance_source_face(const Image& env, uint32_t source_mip);

// The image the pass keeps the source mip's texels in, each as its direction and its radiance x
// solid angle side by side (irradiance_sources.comp); made again only when `sources` does not fit.
void fit_irradiance_sources(Context& gpu, const std::string& name, const Image& env, uint32_t source_mip,
                            Image& sources);

// Records `irradiance` (rgba16f cube, GENERAL, mip 0) from `env` (READ_ONLY_OPTIMAL) as lights
// of irradiance_source_face(env, source_mip) texels a face, through `sources`
// (fit_irradiance_sources; its contents are not kept).
void record_irradiance(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                       uint32_t source_mip, Image& env, VkSampler sampler, Image& sources, Image& irradiance);

std::unique_ptr<NodeKernel> make_irradiance_kernel(const PlanNode& node);

}  // namespace lg
