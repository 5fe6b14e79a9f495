#include "tests/lighting/occluded_irradiance.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>

#include "nodes/raytrace/ray_offset.h"

namespace lg::test {

double luminance(const glm::dvec3& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

OccludedIrradiance occluded_irradiance(const RayScene& scene, const CubeImage& env, glm::vec3 position,
                                       glm::vec3 geometric, glm::dvec3 shading) {
  const glm::vec3 origin = offset_ray_origin(position, geometric);
  OccludedIrradiance out;
  for (int f = 0; f < 6; ++f)
    for (uint32_t j = 0; j < env.size; ++j)
      for (uint32_t i = 0; i < env.size; ++i) {
        const glm::dvec3 d = glm::normalize(env.direction(f, i, j));
        const double cosine = glm::dot(shading, d);
        if (cosine <= 0) continue;
        const glm::dvec3 light = glm::dvec3(env.at(f, i, j)) * texel_solid_angle(env.size, i, j) * cosine;
        out.open += light;
        if (!scene.occluded(origin, glm::vec3(d), std::numeric_limits<float>::infinity())) out.reference += light;
      }
  return out;
}

ErrorStats error_stats(std::vector<double> errors) {
  std::sort(errors.begin(), errors.end());
  return {std::accumulate(errors.begin(), errors.end(), 0.0) / errors.size(),
          errors[std::min(errors.size() - 1, size_t(std::ceil(0.95 * errors.size())) - 1)]};
}

MeanAndError mean_and_error(const std::vector<double>& values) {
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  double var = 0;
  for (double v : values) var += (v - mean) * (v - mean);
  return {mean, std::sqrt(var / (values.size() - 1) / values.size())};
}

}  // namespace lg::test
