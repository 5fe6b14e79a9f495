#include "nodes/gi/path_tracer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/gi/path_tracer/path_transport.h"
#include "nodes/raytrace/camera_pixels.h"
#include "nodes/raytrace/parallel_for.h"

namespace lg {
namespace {

glm::dvec3 aov_of(const PathValue& v, ReferenceAov aov) {
  switch (aov) {
    case ReferenceAov::radiance:
      return v.radiance();
    case ReferenceAov::emission:
      return v.emission;
    case ReferenceAov::direct:
      return v.direct;
    case ReferenceAov::indirect_diffuse:
      return v.indirect_diffuse;
    case ReferenceAov::specular:
      return v.specular;
  }
  return glm::dvec3(0.0);
}

bool finite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

const char* reference_aov_name(ReferenceAov aov) {
  switch (aov) {
    case ReferenceAov::radiance:
      return "radiance";
    case ReferenceAov::emission:
      return "emission";
    case ReferenceAov::direct:
      return "direct";
    case ReferenceAov::indirect_diffuse:
      return "indirect_diffuse";
    case ReferenceAov::specular:
      return "specular";
  }
  return "?";
}

std::optional<ReferenceAov> parse_reference_aov(const std::string& name) {
  for (size_t i = 0; i < kReferenceAovCount; ++i)
    if (name == reference_aov_name(ReferenceAov(i))) return ReferenceAov(i);
  return std::nullopt;
}

ReferenceImage trace_reference(const PathScene& scene, const PathTracerOptions& options,
                               const std::function<void(size_t)>& progress) {
  ReferenceImage out;
  out.width = options.width, out.height = options.height;
  out.row_begin = std::min(options.row_begin, options.height);
  out.row_end = options.row_end == 0 ? options.height : std::min(options.row_end, options.height);
  out.row_end = std::max(out.row_end, out.row_begin);
  for (size_t a = 0; a < kReferenceAovCount; ++a) {
    out.mean[a].assign(out.pixel_count(), glm::vec3(0.0f));
    out.standard_error[a].assign(out.pixel_count(), glm::vec3(0.0f));
  }
  if (out.pixel_count() == 0) return out;
  const CameraPixels pixels(scene.view().camera, options.width, options.height);
  const PathTransport transport(scene, options.max_bounces, options.russian_roulette_after);
  const uint32_t n = std::max(options.samples_per_pixel, 1u);
  std::vector<uint32_t> dropped(out.pixel_count(), 0);
  auto trace_pixel = [&](size_t i) {
    const uint32_t x = uint32_t(i % options.width), y = out.row_begin + uint32_t(i / options.width);
    const uint64_t pixel = uint64_t(y) * options.width + x;
    const glm::dvec3 direction = pixels.ray_direction(x, y);
    std::array<glm::dvec3, kReferenceAovCount> sum{}, sum_squares{};
    for (uint32_t k = 0; k < n; ++k) {
      const PathRandom random(options.seed, pixel * n + k, transport.dimensions_per_bounce());
      const PathValue value = transport.camera_path(pixels.eye(), direction, options.cull_backfaces, random);
      std::array<glm::dvec3, kReferenceAovCount> v;
      bool ok = true;
      for (size_t a = 0; a < kReferenceAovCount; ++a) ok = ok && finite(v[a] = aov_of(value, ReferenceAov(a)));
      if (!ok) {
        ++dropped[i];
        continue;
      }
      for (size_t a = 0; a < kReferenceAovCount; ++a) sum[a] += v[a], sum_squares[a] += v[a] * v[a];
    }
    for (size_t a = 0; a < kReferenceAovCount; ++a) {
      const glm::dvec3 mean = sum[a] / double(n);
      // The unbiased variance of one path's value, over n for the mean's.
      const glm::dvec3 variance =
          n > 1 ? glm::max(sum_squares[a] / double(n) - mean * mean, 0.0) * (double(n) / (n - 1)) : glm::dvec3(0.0);
      out.mean[a][i] = glm::vec3(mean);
      out.standard_error[a][i] = glm::vec3(glm::sqrt(variance / double(n)));
    }
  };
  if (progress)
    parallel_for_with_progress(out.pixel_count(), trace_pixel, progress);
  else
    parallel_for(out.pixel_count(), trace_pixel);
  for (uint32_t d : dropped) out.non_finite_samples += d;
  return out;
}

}  // namespace lg
