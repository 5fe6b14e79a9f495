#include "nodes/occlusion/reference/ao_sampling.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "nodes/raytrace/cosine_sampling.h"
#include "nodes/occlusion/estimate/occlusion_estimate.h"

namespace lg {

double occlusion_weight(double distance, const AoSettings& settings) {
  if (!std::isfinite(distance)) return 0.0;  // no hit
  if (!std::isfinite(settings.max_distance)) return 1.0;
  const double from = settings.falloff_from * settings.max_distance;
  if (distance <= from) return 1.0;
  if (distance >= settings.max_distance) return 0.0;
  return (settings.max_distance - distance) / (settings.max_distance - from);
}

std::vector<glm::dvec3> cosine_directions(glm::dvec3 normal, const AoSettings& settings, uint64_t pixel) {
  const Frame frame = make_frame(normal);
  const uint64_t seed = point_seed(settings.seed, pixel);
  std::vector<glm::dvec3> out;
  out.reserve(size_t(settings.rays));
  for (int i = 0; i < settings.rays; ++i)
    out.push_back(glm::normalize(
        frame.to_world(cosine_hemisphere(stratified_point(uint32_t(i), uint32_t(settings.rays), seed)))));
  return out;
}

void OcclusionSum::add(glm::dvec3 direction, double weight) {
  visible_ += 1.0 - weight;
  bent_ += direction * (1.0 - weight);
  ++count_;
}

double OcclusionSum::visibility() const {
  return count_ > 0 ? visible_ / count_ : 1.0;
}

glm::dvec4 OcclusionSum::bent_normal_and_cone(glm::dvec3 normal) const {
  const double k = visibility();
  const double length = glm::length(bent_);
  const glm::dvec3 bent = length > 1e-12 ? bent_ / length : normal;
  return {bent, std::sqrt(std::max(0.0, 1.0 - k))};
}

}  // namespace lg
