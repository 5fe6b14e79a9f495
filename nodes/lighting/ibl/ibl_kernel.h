// The kernel of lighting.ibl, and the pass it records (which tests run directly): image-based
// light of the G-buffer from the env nodes' outputs (nodes/lighting/ibl/shaders/ibl.comp).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "runtime/exec/node_kernel.h"
#include "runtime/gpu/buffer.h"
#include "runtime/gpu/image.h"

namespace lg {

struct IblSettings {
  bool diffuse_from_sh = true;  // else from the irradiance map
  float intensity = 1.0f;       // 0 for a scene without an environment (a volume's light only)
  bool specular_occlusion = true;
  bool multi_bounce = true;
};

// What the pass reads and writes; optional inputs may be null. Sampled images are in
// READ_ONLY_OPTIMAL, `color` (rgba16f) in GENERAL; `camera` holds CameraConstants.
struct IblInputs {
  VkBuffer camera = VK_NULL_HANDLE;
  Image *depth = nullptr, *normal = nullptr, *albedo = nullptr, *material = nullptr;
  Image* direct = nullptr;
  const Buffer* sh = nullptr;
  Image* irradiance = nullptr;
  Image *specular = nullptr, *brdf_lut = nullptr;
  Image *ao = nullptr, *bent_normals = nullptr;
  Image* irradiance_volume = nullptr;  // rgb irradiance (W/m^2), a coverage
  Image* ssr = nullptr;                // rgb reflected radiance before the BRDF, a confidence
  Image* reflection_probes = nullptr;  // the same from gi.reflection_capture, a its coverage
  Image* color = nullptr;
};

// 1x1 stand-ins, all zero, bound where an optional input is unlinked (every binding a pipeline
// uses needs a valid descriptor); cleared by the first pass that records with them.
class IblFallbacks {
 public:
  explicit IblFallbacks(Context& gpu);
  void prepare(VkCommandBuffer cmd);  // records the clears once

  Image direct, ao, bent_normals, irradiance;
  Buffer sh;

 private:
  bool cleared_ = false;
};

// The G-buffer and direct light are fetched through `nearest`, the rest filtered by `linear`.
void record_ibl(Context& gpu, PipelineCache& pipelines, VkCommandBuffer cmd, const std::string& name,
                const IblSettings& settings, const IblInputs& inputs, IblFallbacks& fallbacks, VkSampler linear,
                VkSampler nearest);

std::unique_ptr<NodeKernel> make_ibl_kernel(const PlanNode& node);

}  // namespace lg
