#include "tests/gi/prt_comparison.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/raytrace/camera_pixels.h"

namespace lg::test {

PrtComparison compare_with_reference(const PathScene& scene, const ReferenceImage& reference,
                                     const std::vector<float>& frame) {
  const PathTransport transport(scene, 1);
  const CameraPixels camera(scene.view().camera, reference.width, reference.height);
  double square = 0, noise = 0, absolute_square = 0, absolute_noise = 0, truth_sum = 0, frame_sum = 0;
  PrtComparison out;
  for (uint32_t y = 0; y < reference.height; ++y)
    for (uint32_t x = 0; x < reference.width; ++x) {
      const size_t i = size_t(y) * reference.width + x;
      const auto surface = transport.visible_surface(camera.eye(), camera.ray_direction(x, y), true);
      if (!surface || frame[4 * i + 3] < 1.0f) continue;
      for (int c = 0; c < 3; ++c) {
        if (!(surface->diffuse_color[c] > 0.0)) continue;
        const double to_irradiance = std::numbers::pi / surface->diffuse_color[c];
        const double truth = reference.mean_of(ReferenceAov::indirect_diffuse)[i][c] * to_irradiance;
        const double error = reference.error_of(ReferenceAov::indirect_diffuse)[i][c] * to_irradiance;
        if (!(truth > 0.0)) continue;
        square += std::pow((frame[4 * i + c] - truth) / truth, 2);
        noise += std::pow(error / truth, 2);
        absolute_square += std::pow(frame[4 * i + c] - truth, 2);
        absolute_noise += error * error;
        truth_sum += truth;
        frame_sum += frame[4 * i + c];
        ++out.values;
      }
    }
  if (out.values == 0) return out;
  out.relative_rms = std::sqrt(square / out.values);
  out.reference_noise = std::sqrt(noise / out.values);
  out.beyond_noise = std::sqrt(std::max(0.0, square - noise) / out.values);
  const double mean = truth_sum / out.values;
  out.rms_over_mean = std::sqrt(absolute_square / out.values) / mean;
  out.noise_over_mean = std::sqrt(absolute_noise / out.values) / mean;
  out.mean_over_mean = frame_sum / truth_sum;
  return out;
}

}  // namespace lg::test
