// The kernel of env.load, and the pass it records (which tests run directly): an
// equirectangular HDR or EXR file (nodes/env/common/equirect.h states the mapping) resampled
// to a cube map, then every mip by solid-angle-weighted box filtering. Non-finite texels of
// the file are replaced by 0, counted, and reported on stderr. The file is read straight into
// the upload's staging buffer at the first record, and both float copies of it are freed when
// that frame has finished (NodeKernel::frame_finished).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"
#include "runtime/image/image_file.h"

namespace lg {

// Samples per cube texel along each axis: enough to cover the equirect texels it spans.
uint32_t equirect_supersample(uint32_t equirect_width, uint32_t face_size);

// The equirect image on the device (rgba32f) and the host-visible staging buffer it is uploaded
// from. The texels are written straight into the staging buffer (file reads, sanitising), so
// the host holds one float copy of the image; on lavapipe, whose device memory is host memory,
// the image is the second.
class EquirectSource {
 public:
  EquirectSource(Context& gpu, uint32_t width, uint32_t height);
  // The staging buffer as RGBA floats, rows top to bottom: fill it before upload().
  std::span<float> texels();
  // Records the copy into the image (every time: a frame that failed after recording it never
  // ran the copy); leaves the image in READ_ONLY_OPTIMAL.
  void upload(VkCommandBuffer cmd);

  Image image;

 private:
  Buffer staging_;
};

// What env.load does at its first record: a source of `file`'s size, the file read straight into
// its staging buffer and sanitised there (scaled by `intensity`); `non_finite` gets the count
// of replaced texels.
EquirectSource read_equirect(Context& gpu, ImageReader& file, double intensity, uint64_t& non_finite);

// Records every mip of `cube` (rgba16f cube map in GENERAL) from `source`.
void record_env_load(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                     EquirectSource& source, VkSampler nearest, Image& cube);

std::unique_ptr<NodeKernel> make_env_load_kernel(const PlanNode& node);

}  // namespace lg
