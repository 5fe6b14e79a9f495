// The kernel of env.load, and the pass it records (which tests run directly): an
// equirectangular HDR or EXR file (nodes/env/common/equirect.h states the mapping) resampled
// to a cube map, then every mip by solid-angle-weighted box filtering. Non-finite texels of
// the file are replaced by 0, counted, and reported on stderr.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"

namespace lg {

// The image as the GPU gets it: RGBA floats, rows top to bottom, scaled and sanitised.
struct EquirectPixels {
  uint32_t width = 0, height = 0;
  std::vector<float> rgba;
  uint64_t non_finite = 0;  // texels that held NaN or Inf, now 0
};

// Scales by `intensity` and replaces non-finite texels by 0, counting them.
EquirectPixels sanitize_equirect(uint32_t width, uint32_t height, std::vector<float> rgba, double intensity);

// Samples per cube texel along each axis: enough to cover the equirect texels it spans.
uint32_t equirect_supersample(uint32_t equirect_width, uint32_t face_size);

// The equirect image on the device (rgba32f), uploaded by the first pass that records with it.
class EquirectSource {
 public:
  EquirectSource(Context& gpu, const EquirectPixels& pixels);
  void upload(VkCommandBuffer cmd);  // once; leaves the image in READ_ONLY_OPTIMAL

  Image image;

 private:
  Buffer staging_;
  bool uploaded_ = false;
};

// Records every mip of `cube` (rgba16f cube map in GENERAL) from `source`.
void record_env_load(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                     EquirectSource& source, VkSampler nearest, Image& cube);

std::unique_ptr<NodeKernel> make_env_load_kernel(const PlanNode& node);

}  // namespace lg
