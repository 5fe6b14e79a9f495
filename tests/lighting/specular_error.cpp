#include "tests/lighting/specular_error.h"

#include <cmath>

#include "runtime/scene/make_scene_view.h"

namespace lg::test {

bool SurfaceMask::contains(const float* material) const {
  return material[1] > 0.5f && (roughness < 0.0f || std::abs(material[0] - roughness) < 0.005f);
}

SpecularError specular_error(const ReferenceImage& reference, const std::vector<float>& lit,
                             const std::vector<float>& direct, const std::vector<float>& material, SurfaceMask mask) {
  const auto& mean = reference.mean_of(ReferenceAov::specular);
  const auto& error = reference.error_of(ReferenceAov::specular);
  double truth_sum = 0, error_sum = 0, noise_sum = 0;
  SpecularError out;
  for (size_t i = 0; i < reference.pixel_count(); ++i) {
    if (!mask.contains(&material[4 * i])) continue;
    ++out.pixels;
    for (int c = 0; c < 3; ++c) {
      truth_sum += mean[i][c];
      error_sum += std::abs(lit[4 * i + c] - direct[4 * i + c] - mean[i][c]);
      noise_sum += error[i][c];
    }
  }
  if (truth_sum > 0) out.relative = error_sum / truth_sum, out.noise = noise_sum / truth_sum;
  return out;
}

ReferenceImage trace_specular_reference(const World& world, uint32_t width, uint32_t height, uint32_t paths,
                                        const PathEnvironment& environment) {
  const PathScene scene(make_scene_view(world, float(width) / float(height)), environment);
  PathTracerOptions o;
  o.width = width, o.height = height, o.samples_per_pixel = paths;
  return trace_reference(scene, o);
}

}  // namespace lg::test
